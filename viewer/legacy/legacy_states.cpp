#include "legacy/legacy_states.hpp"

#include <map>

#include "core/text.hpp"
#include "effect/texture_annotations.hpp"

namespace fxview::legacy {
namespace {

void warn_once(const std::string& name, const std::string& message, const effect::SourceLocation& where,
               std::vector<std::string>& warnings, std::set<std::string>& warned) {
    if (warned.insert(to_lower(name)).second) warnings.push_back(where.str() + ": warning: " + message);
}

// The words and numbers of a state value; constructor names (int2, float4, bool4) and punctuation dropped.
effect::StateValue state_value(const std::vector<effect::Token>& tokens) {
    effect::StateValue value;
    bool negative = false;
    for (size_t i = 0; i < tokens.size(); ++i) {
        const effect::Token& t = tokens[i];
        if (t.kind == effect::TokenKind::Punct) {
            negative = t.text == "-";
            continue;
        }
        if (t.kind == effect::TokenKind::Identifier && i + 1 < tokens.size() && tokens[i + 1].text == "(") continue;
        if (t.kind == effect::TokenKind::Number) {
            std::string text = t.text;
            while (!text.empty() && (text.back() == 'f' || text.back() == 'F')) text.pop_back();
            double number = 0;
            try {
                number = text.rfind("0x", 0) == 0 ? static_cast<double>(std::stoul(text, nullptr, 16)) : std::stod(text);
            } catch (const std::exception&) {
                number = 0;
            }
            value.numbers.push_back(negative ? -number : number);
            value.is_number.push_back(true);
        } else {
            value.words.push_back(t.text);
            value.is_number.push_back(false);
        }
        negative = false;
    }
    return value;
}

std::string lower_word(const effect::StateValue& v) { return v.words.size() == 1 && v.is_number.size() == 1 ? to_lower(v.words[0]) : ""; }

bool truth(const effect::StateValue& v, bool& ok) {
    ok = v.is_number.size() == 1;
    if (!ok) return false;
    if (v.is_number[0]) return v.numbers[0] != 0;
    const std::string w = to_lower(v.words[0]);
    ok = w == "true" || w == "false" || w == "d3dzb_true" || w == "d3dzb_false";
    return w == "true" || w == "d3dzb_true";
}

const std::map<std::string, GLenum> kDxBlend = {
    {"zero", GL_ZERO},         {"one", GL_ONE},
    {"srccolor", GL_SRC_COLOR}, {"invsrccolor", GL_ONE_MINUS_SRC_COLOR},
    {"srcalpha", GL_SRC_ALPHA}, {"invsrcalpha", GL_ONE_MINUS_SRC_ALPHA},
    {"destalpha", GL_DST_ALPHA}, {"invdestalpha", GL_ONE_MINUS_DST_ALPHA},
    {"destcolor", GL_DST_COLOR}, {"invdestcolor", GL_ONE_MINUS_DST_COLOR},
    {"srcalphasat", GL_SRC_ALPHA_SATURATE}};
const std::map<std::string, GLenum> kDxBlendOp = {{"add", GL_FUNC_ADD}, {"subtract", GL_FUNC_SUBTRACT},
                                                  {"revsubtract", GL_FUNC_REVERSE_SUBTRACT}, {"min", GL_MIN}, {"max", GL_MAX}};
const std::map<std::string, GLenum> kDxCompare = {{"never", GL_NEVER},         {"less", GL_LESS},      {"equal", GL_EQUAL},
                                                  {"lessequal", GL_LEQUAL},    {"greater", GL_GREATER}, {"notequal", GL_NOTEQUAL},
                                                  {"greaterequal", GL_GEQUAL}, {"always", GL_ALWAYS}};
// Fixed-function states of DX9 and CgFX that a core profile has no equivalent for.
const std::set<std::string> kFixedFunction = {
    "lighting", "lightingenable", "fogenable", "alphatestenable", "alphafunc", "alpharef", "shademode", "shademodel",
    "specularenable", "normalizenormals", "colorvertex", "stencilenable", "stencilfunc", "stencilref", "stencilmask",
    "stencilwritemask", "stencilfail", "stencilzfail", "stencilpass", "stencilop", "pointsize", "pointspriteenable",
    "multisampleantialias", "dithering", "ditherenable", "texture2denable", "lightmodeltwosideenable", "frontface",
    "srcblendalpha", "destblendalpha", "separatealphablendenable", "blendopalpha", "depthbias", "slopescaledepthbias",
    "scissortestenable", "pointspriteenable", "vertexprogrampointsizeenable", "srgbwriteenable", "alphablendenable_"};

bool set_dx9_state(effect::RenderStates& s, const std::string& key, const effect::StateValue& v, bool& ok) {
    ok = true;
    auto lookup = [&](const std::map<std::string, GLenum>& table, GLenum& out) {
        const auto found = table.find(lower_word(v));
        ok = found != table.end();
        if (ok) out = found->second;
    };
    if (key == "zenable") s.depth_test = truth(v, ok);
    else if (key == "alphablendenable") s.blend = truth(v, ok);
    else if (key == "srcblend") lookup(kDxBlend, s.blend_src);
    else if (key == "destblend") lookup(kDxBlend, s.blend_dst);
    else if (key == "blendop") lookup(kDxBlendOp, s.blend_equation);
    else if (key == "zfunc") lookup(kDxCompare, s.depth_func);
    else if (key == "cullmode") {
        // DirectX's front faces are clockwise in its left-handed frame; with fxview's counter-clockwise
        // fronts, CCW (the DirectX default) culls back faces and CW front faces.
        const std::string w = lower_word(v);
        ok = w == "none" || w == "cw" || w == "ccw" || w == "back" || w == "front" || w == "frontandback";
        s.cull = w != "none";
        s.cull_face = w == "cw" || w == "front" ? GL_FRONT : w == "frontandback" ? GL_FRONT_AND_BACK : GL_BACK;
    } else if (key == "fillmode") {
        const std::string w = lower_word(v);
        ok = w == "solid" || w == "wireframe" || w == "point";
        s.polygon_mode = w == "wireframe" ? GL_LINE : w == "point" ? GL_POINT : GL_FILL;
    } else if (key == "colorwriteenable" || key == "colorwriteenable0") {
        unsigned mask = 0;
        for (size_t i = 0, w = 0, n = 0; i < v.is_number.size(); ++i) {
            if (v.is_number[i]) { mask |= static_cast<unsigned>(v.numbers[n++]); continue; }
            const std::string word = to_lower(v.words[w++]);
            mask |= word == "red" ? 1u : word == "green" ? 2u : word == "blue" ? 4u : word == "alpha" ? 8u : word == "true" ? 15u : 0u;
        }
        s.color_mask = {(mask & 1u) != 0, (mask & 2u) != 0, (mask & 4u) != 0, (mask & 8u) != 0};
    } else {
        return false;
    }
    return true;
}

}  // namespace

void set_legacy_render_state(effect::RenderStates& states, const std::string& name, const std::vector<effect::Token>& tokens,
                             const effect::SourceLocation& where, std::vector<std::string>& warnings, std::set<std::string>& warned) {
    const std::string key = to_lower(name);
    const effect::StateValue value = state_value(tokens);
    if (kFixedFunction.count(key)) {
        warn_once(name,
                  key == "frontface" ? "render state " + name + " is not supported: front faces stay counter-clockwise (fxview's meshes wind them so)"
                                     : "render state " + name + " has no equivalent in OpenGL core and is ignored",
                  where, warnings, warned);
        return;
    }
    bool ok = true;
    if (set_dx9_state(states, key, value, ok)) {
        if (!ok) warn_once(name, "render state " + name + ": value not understood, the default is kept", where, warnings, warned);
        return;
    }
    if (key == "polygonmode" && value.words.size() == 2) {  // CgFX: int2(FrontAndBack, Fill)
        effect::StateValue mode;
        mode.words = {value.words[1]};
        mode.is_number = {false};
        try { effect::set_render_state(states, name, mode, where); } catch (const effect::EffectError&) {}
        return;
    }
    try {
        effect::set_render_state(states, name, value, where);
    } catch (const effect::EffectError& error) {
        const std::string message = error.what();
        const bool unknown = message.find("unknown render state") != std::string::npos;
        warn_once(name, unknown ? "unknown render state " + name + " ignored" : message.substr(message.find(": ") + 2) + " (ignored)",
                  where, warnings, warned);
    }
}

void set_legacy_sampler_state(effect::SamplerState& sampler, const std::string& name, const std::string& value,
                              const effect::SourceLocation& where, std::vector<std::string>& warnings, std::set<std::string>& warned) {
    const std::string key = to_lower(name);
    const std::string v = to_lower(value);
    // DirectX 9 splits the minifying filter into MinFilter and MipFilter.
    const bool mip_linear = sampler.min_filter == GL_LINEAR_MIPMAP_LINEAR || sampler.min_filter == GL_NEAREST_MIPMAP_LINEAR;
    const bool mip_any = sampler.min_filter != GL_LINEAR && sampler.min_filter != GL_NEAREST;
    const bool min_linear = sampler.min_filter == GL_LINEAR || sampler.min_filter == GL_LINEAR_MIPMAP_LINEAR ||
                            sampler.min_filter == GL_LINEAR_MIPMAP_NEAREST;
    auto compose = [](bool linear, bool mip, bool mip_lin) -> GLenum {
        if (!mip) return linear ? GL_LINEAR : GL_NEAREST;
        if (linear) return mip_lin ? GL_LINEAR_MIPMAP_LINEAR : GL_LINEAR_MIPMAP_NEAREST;
        return mip_lin ? GL_NEAREST_MIPMAP_LINEAR : GL_NEAREST_MIPMAP_NEAREST;
    };
    const bool dx_filter = v == "point" || v == "linear" || v == "anisotropic" || v == "none" || v == "gaussianquad" || v == "pyramidalquad";
    if (key == "mipfilter") {
        sampler.min_filter = compose(min_linear, v != "none", v != "point");
        return;
    }
    if (key == "minfilter" && dx_filter) {
        sampler.min_filter = compose(v != "point", mip_any, mip_linear);
        return;
    }
    if (key == "magfilter" && dx_filter) {
        sampler.mag_filter = v == "point" ? GL_NEAREST : GL_LINEAR;
        return;
    }
    std::string wrap = v;
    if (v == "border" || v == "clamptoborder" || v == "mirroronce") wrap = "clamp";
    if (v == "mirroredrepeat") wrap = "mirror";
    const bool address = key == "addressu" || key == "addressv" || key == "addressw" || key == "wraps" || key == "wrapt" || key == "wrapr";
    try {
        effect::set_sampler_state(sampler, name, address ? wrap : value, where);
    } catch (const effect::EffectError&) {
        warn_once("sampler:" + key, "sampler state " + name + " = " + excerpt(value) + " ignored", where, warnings, warned);
    }
}

effect::TextureStorage storage_from_format(const std::string& format) {
    const std::string f = to_lower(format);
    if (f.find("32f") != std::string::npos || f.find("32b32") != std::string::npos || f == "r32f" || f == "g32r32f") return effect::TextureStorage::Float32;
    if (f.find("16f") != std::string::npos || f.find("16b16") != std::string::npos) return effect::TextureStorage::Float16;
    if (f.find("8") != std::string::npos) return effect::TextureStorage::Unorm8;
    return effect::TextureStorage::Native;
}

}  // namespace fxview::legacy
