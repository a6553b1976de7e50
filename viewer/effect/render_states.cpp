#include "core/text.hpp"
#include "effect/render_states.hpp"

#include <algorithm>
#include <cctype>
#include <map>

namespace fxview::effect {
namespace {

std::string describe(const StateValue& value) {
    std::string text;
    for (size_t i = 0, w = 0, n = 0; i < value.is_number.size(); ++i)
        text += (i ? "," : "") + (value.is_number[i] ? std::to_string(value.numbers[n++]) : value.words[w++]);
    return text;
}

bool to_bool(const std::string& state, const StateValue& value, const SourceLocation& where) {
    if (value.is_number.size() == 1) {
        if (value.is_number[0]) return value.numbers[0] != 0.0;
        const std::string word = to_lower(value.words[0]);
        if (word == "true") return true;
        if (word == "false") return false;
    }
    throw EffectError(where, "render state " + state + " needs true or false, got '" + describe(value) + "'");
}

GLenum to_enum(const std::string& state, const std::string& word, const std::map<std::string, GLenum>& choices,
               const SourceLocation& where) {
    const auto found = choices.find(to_lower(word));
    if (found != choices.end()) return found->second;
    std::string names;
    for (const auto& [name, _] : choices) names += (names.empty() ? "" : ", ") + name;
    throw EffectError(where, "render state " + state + ": unknown value '" + word + "' (expected one of " + names + ")");
}

GLenum single_enum(const std::string& state, const StateValue& value, const std::map<std::string, GLenum>& choices,
                   const SourceLocation& where) {
    if (value.words.size() != 1 || value.is_number.size() != 1)
        throw EffectError(where, "render state " + state + " needs one name, got '" + describe(value) + "'");
    return to_enum(state, value.words[0], choices, where);
}

std::vector<float> numbers(const std::string& state, const StateValue& value, size_t count, const SourceLocation& where) {
    if (value.numbers.size() != count || value.words.size() != 0)
        throw EffectError(where, "render state " + state + " needs " + std::to_string(count) + " number(s), got '" +
                                     describe(value) + "'");
    return {value.numbers.begin(), value.numbers.end()};
}

const std::map<std::string, GLenum> kCompare = {
    {"never", GL_NEVER}, {"less", GL_LESS},        {"equal", GL_EQUAL},       {"lequal", GL_LEQUAL},
    {"lessequal", GL_LEQUAL}, {"greater", GL_GREATER}, {"notequal", GL_NOTEQUAL}, {"gequal", GL_GEQUAL},
    {"greaterequal", GL_GEQUAL}, {"always", GL_ALWAYS}};
const std::map<std::string, GLenum> kFaces = {{"back", GL_BACK}, {"front", GL_FRONT}, {"frontandback", GL_FRONT_AND_BACK}};
const std::map<std::string, GLenum> kBlendFactors = {
    {"zero", GL_ZERO},
    {"one", GL_ONE},
    {"srccolor", GL_SRC_COLOR},
    {"oneminussrccolor", GL_ONE_MINUS_SRC_COLOR},
    {"dstcolor", GL_DST_COLOR},
    {"oneminusdstcolor", GL_ONE_MINUS_DST_COLOR},
    {"srcalpha", GL_SRC_ALPHA},
    {"oneminussrcalpha", GL_ONE_MINUS_SRC_ALPHA},
    {"dstalpha", GL_DST_ALPHA},
    {"oneminusdstalpha", GL_ONE_MINUS_DST_ALPHA},
    {"srcalphasaturate", GL_SRC_ALPHA_SATURATE}};
const std::map<std::string, GLenum> kEquations = {{"add", GL_FUNC_ADD},   {"funcadd", GL_FUNC_ADD},
                                                  {"subtract", GL_FUNC_SUBTRACT}, {"funcsubtract", GL_FUNC_SUBTRACT},
                                                  {"reversesubtract", GL_FUNC_REVERSE_SUBTRACT},
                                                  {"funcreversesubtract", GL_FUNC_REVERSE_SUBTRACT},
                                                  {"min", GL_MIN}, {"max", GL_MAX}};
const std::map<std::string, GLenum> kPolygonModes = {{"fill", GL_FILL}, {"line", GL_LINE}, {"point", GL_POINT}};

}  // namespace

void set_render_state(RenderStates& s, const std::string& name, const StateValue& value, const SourceLocation& where) {
    const std::string key = to_lower(name);
    if (key == "depthtestenable") {
        s.depth_test = to_bool(name, value, where);
    } else if (key == "depthmask" || key == "depthwriteenable" || key == "zwriteenable") {
        s.depth_write = to_bool(name, value, where);
    } else if (key == "depthfunc" || key == "zfunc") {
        s.depth_func = single_enum(name, value, kCompare, where);
    } else if (key == "cullfaceenable") {
        s.cull = to_bool(name, value, where);
    } else if (key == "cullface") {
        s.cull_face = single_enum(name, value, kFaces, where);
    } else if (key == "cullmode") {  // DirectX spelling: None disables culling
        if (value.words.size() == 1 && to_lower(value.words[0]) == "none") {
            s.cull = false;
        } else {
            s.cull = true;
            s.cull_face = single_enum(name, value, kFaces, where);
        }
    } else if (key == "blendenable") {
        s.blend = to_bool(name, value, where);
    } else if (key == "blendfunc") {
        if (value.words.size() != 2 || value.is_number.size() != 2)
            throw EffectError(where, "render state BlendFunc needs (source, destination), got '" + describe(value) + "'");
        s.blend_src = to_enum(name, value.words[0], kBlendFactors, where);
        s.blend_dst = to_enum(name, value.words[1], kBlendFactors, where);
    } else if (key == "blendequation") {
        s.blend_equation = single_enum(name, value, kEquations, where);
    } else if (key == "colormask" || key == "colorwriteenable") {
        if (value.is_number.size() != 4)
            throw EffectError(where, "render state ColorMask needs four booleans (r, g, b, a)");
        for (size_t i = 0, w = 0, n = 0; i < 4; ++i) {
            StateValue one;
            one.is_number = {value.is_number[i]};
            if (value.is_number[i]) one.numbers = {value.numbers[n++]};
            else one.words = {value.words[w++]};
            s.color_mask[i] = to_bool(name, one, where);
        }
    } else if (key == "polygonmode" || key == "fillmode") {
        s.polygon_mode = single_enum(name, value, kPolygonModes, where);
    } else if (key == "clear") {
        s.clear = to_bool(name, value, where);
    } else if (key == "clearcolor") {
        const auto c = numbers(name, value, 4, where);
        s.clear_color = std::array<float, 4>{c[0], c[1], c[2], c[3]};
        s.clear = true;
    } else if (key == "cleardepth") {
        s.clear_depth = numbers(name, value, 1, where)[0];
        s.clear = true;
    } else if (key == "rendertarget") {  // RenderTarget = A; or RenderTarget = (A, B);
        if (value.words.empty() || value.words.size() != value.is_number.size())
            throw EffectError(where, "render state RenderTarget needs one or more target names");
        s.render_targets = value.words;
    } else if (key.rfind("rendercolortarget", 0) == 0 && key.size() == 18 && key[17] >= '0' && key[17] <= '7') {
        if (value.words.size() != 1 || value.is_number.size() != 1)
            throw EffectError(where, "render state " + name + " needs a target name");
        const size_t index = static_cast<size_t>(key[17] - '0');
        if (s.render_targets.size() <= index) s.render_targets.resize(index + 1);
        s.render_targets[index] = value.words[0];
    } else if (key == "draw") {
        const std::string what = value.words.size() == 1 ? to_lower(value.words[0]) : "";
        if (what != "geometry" && what != "buffer")
            throw EffectError(where, "render state Draw needs Geometry or Buffer, got '" + describe(value) + "'");
        s.draw_buffer = what == "buffer";
    } else {
        throw EffectError(where, "unknown render state '" + name + "'");
    }
}

void apply_render_states(const RenderStates& s) {
    s.depth_test ? glEnable(GL_DEPTH_TEST) : glDisable(GL_DEPTH_TEST);
    glDepthMask(s.depth_write ? GL_TRUE : GL_FALSE);
    glDepthFunc(s.depth_func);
    s.cull ? glEnable(GL_CULL_FACE) : glDisable(GL_CULL_FACE);
    glCullFace(s.cull_face);
    s.blend ? glEnable(GL_BLEND) : glDisable(GL_BLEND);
    glBlendFunc(s.blend_src, s.blend_dst);
    glBlendEquation(s.blend_equation);
    glColorMask(s.color_mask[0], s.color_mask[1], s.color_mask[2], s.color_mask[3]);
    glPolygonMode(GL_FRONT_AND_BACK, s.polygon_mode);
}

}  // namespace fxview::effect
