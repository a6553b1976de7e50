// The effect format's grammar (docs/effect-format.md): parameters, textures, shader blocks, techniques
// and passes, plugins, and the checks across them; load_effect() runs it or the legacy Cg/HLSL path.
#include "core/text.hpp"
#include "effect/parser.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <map>
#include <set>
#include <unordered_map>
#include <unordered_set>

#include "effect/lexer.hpp"
#include "effect/token_reader.hpp"
#include "effect/parameter_values.hpp"
#include "effect/semantics.hpp"
#include "effect/texture_annotations.hpp"
#include "legacy/legacy_effect.hpp"

namespace fxview::effect {

namespace {

// The effect format's grammar (docs/effect-format.md) over the tokens TokenReader reads.
class Parser : TokenReader {
public:
    Parser(Effect& effect) : TokenReader(effect.sources), effect_(effect) {}

    void parse() {
        for (;;) {
            const Token token = lexer_.peek();
            check_unterminated();
            if (token.kind == TokenKind::End) break;
            if (token.kind == TokenKind::Preprocessor) {
                lexer_.next();
                effect_.globals += effect_.sources.glsl(token.begin, token.end);
            } else if (token.kind == TokenKind::Identifier && token.text == "uniform") {
                parse_parameter();
            } else if (token.kind == TokenKind::Identifier && (token.text == "GLSLShader" || token.text == "shader")) {
                parse_shader_block();
            } else if (token.kind == TokenKind::Identifier &&
                       (token.text == "texture" || token.text == "texture1D" || token.text == "texture2D" ||
                        token.text == "texture3D" || token.text == "textureCUBE")) {
                parse_texture();
            } else if (token.kind == TokenKind::Identifier && token.text == "technique") {
                parse_technique();
            } else if (token.kind == TokenKind::Identifier && token.text == "plugin") {
                parse_plugin();
            } else {
                parse_glsl_declaration();
            }
        }
        check_references();
    }

private:
    void parse_parameter() {
        const Token keyword = next();  // uniform
        Parameter parameter;
        parameter.where = at(keyword);
        parameter.type = expect_identifier("a type after 'uniform'").text;
        const Token name = expect_identifier("a parameter name after '" + parameter.type + "'");
        parameter.name = name.text;
        if (const auto first = parameter_index_.find(parameter.name); first != parameter_index_.end())
            fail(name, "parameter '" + parameter.name + "' declared twice (first at " + effect_.parameters[first->second].where.str() + ")");
        count_declaration(name, parameter_index_.size(), "parameters");
        if (accept('[')) {
            const Token size = next();
            if (size.kind != TokenKind::Number) fail(size, "expected an array size");
            const double elements = parse_number(size, false);
            if (!(elements >= 1) || elements != std::floor(elements)) fail(size, "array size must be a positive whole number");
            if (elements > static_cast<double>(effect_.limits.array_elements))
                fail(size, "array of " + excerpt(size.text) + " elements exceeds the budget array-elements = " +
                               std::to_string(effect_.limits.array_elements) + " (raise it with --limit array-elements=N)");
            parameter.array_size = static_cast<int>(elements);
            expect(']', "after the array size");
        }
        if (accept(':')) parameter.semantic = expect_identifier("a semantic after ':'").text;
        std::transform(parameter.semantic.begin(), parameter.semantic.end(), parameter.semantic.begin(),
                       [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
        if (!is_sampler_type(parameter.type) && component_count(parameter.type) == 0)
            fail(keyword, "unknown parameter type '" + parameter.type + "'");
        if (!parameter.semantic.empty() && !is_known_semantic(parameter.semantic))
            fail(name, "unknown semantic '" + parameter.semantic + "' on " + parameter.name);
        parameter.annotations = parse_annotations();
        if (is_sampler_type(parameter.type)) {
            parse_sampler(parameter, name);
        } else if (accept('=')) {
            const Token first = lexer_.peek();
            parameter.default_value = parse_value();
            check_default(parameter, first);
        }
        expect(';', "after the declaration of " + parameter.name);
        parameter.ui = ui_hints_from(parameter.annotations);
        parameter_index_.emplace(parameter.name, effect_.parameters.size());
        effect_.parameters.push_back(std::move(parameter));
    }

    // A sampler reads a texture named in a sampler_state block (CgFX), in a `Texture` annotation,
    // or declared by its own ResourceName annotations (an implicit texture of the same name).
    void parse_sampler(Parameter& parameter, const Token& name) {
        apply_sampler_annotations(parameter.sampler, parameter.annotations);
        for (const auto& a : parameter.annotations)
            if (to_lower(a.name) == "texture") {
                if (!a.value.is_string) throw EffectError(a.where, "annotation Texture needs a texture name string");
                parameter.texture = a.value.text;
            }
        TextureResource implicit;
        implicit.name = parameter.name;
        implicit.where = parameter.where;
        implicit.type = parameter.type == "sampler1D"   ? texture::TextureType::Tex1D
                      : parameter.type == "sampler3D"   ? texture::TextureType::Tex3D
                      : parameter.type == "samplerCube" ? texture::TextureType::Cube
                                                        : texture::TextureType::Tex2D;
        if (apply_texture_annotations(implicit, parameter.annotations)) {
            if (implicit.files.empty()) throw EffectError(parameter.where, "sampler " + parameter.name + " has texture annotations but no ResourceName");
            implicit.annotations = parameter.annotations;
            add_texture(std::move(implicit), name);
            parameter.texture = parameter.name;
        }
        if (!accept('=')) return;
        const Token keyword = expect_identifier("sampler_state after '='");
        if (keyword.text != "sampler_state") fail(keyword, "a sampler's value must be sampler_state { ... }");
        const Token open = expect('{', "to open sampler_state");
        while (!accept('}')) {
            const Token state = next();
            if (state.kind == TokenKind::End) fail(open, "unterminated sampler_state: '{' is never closed");
            if (state.kind != TokenKind::Identifier) fail(state, "expected a sampler state name, found '" + state.text + "'");
            expect('=', "after " + state.text);
            if (to_lower(state.text) == "texture") {
                const bool angled = accept('<');
                parameter.texture = expect_identifier("a texture name").text;
                texture_uses_.push_back({state, parameter.texture});
                if (angled) expect('>', "after the texture name");
            } else {
                const Token value = expect_identifier("a sampler state value");
                set_sampler_state(parameter.sampler, state.text, value.text, at(value));
            }
            expect(';', "after the value of " + state.text);
        }
    }

    void add_texture(TextureResource texture, const Token& name) {
        if (const auto first = texture_index_.find(texture.name); first != texture_index_.end())
            fail(name, "texture '" + texture.name + "' declared twice (first at " + effect_.textures[first->second].where.str() + ")");
        count_declaration(name, texture_index_.size(), "textures");
        texture_index_.emplace(texture.name, effect_.textures.size());
        effect_.textures.push_back(std::move(texture));
    }

    // texture NAME [: RENDERCOLORTARGET] < annotations >;
    void parse_texture() {
        const Token keyword = next();
        TextureResource texture;
        if (keyword.text == "texture1D") texture.type = texture::TextureType::Tex1D;
        if (keyword.text == "textureCUBE") texture.type = texture::TextureType::Cube;
        if (keyword.text == "texture3D") texture.type = texture::TextureType::Tex3D;
        const Token name = expect_identifier("a texture name");
        texture.name = name.text;
        texture.where = at(name);
        if (accept(':')) {
            const Token semantic = expect_identifier("a texture semantic after ':'");
            if (to_lower(semantic.text) != "rendercolortarget")
                fail(semantic, "unknown texture semantic '" + semantic.text + "' (expected RENDERCOLORTARGET)");
            texture.render_target = true;
            texture.storage = TextureStorage::Float32;
        }
        texture.annotations = parse_annotations();
        apply_texture_annotations(texture, texture.annotations);
        expect(';', "after the declaration of texture " + texture.name);
        if (texture.render_target && !texture.files.empty())
            fail(name, "render target " + texture.name + " cannot have a ResourceName");
        if (texture.render_target && texture.type != texture::TextureType::Tex2D)
            fail(name, "render target " + texture.name + " must be 2D");
        if (!texture.render_target && texture.files.empty())
            fail(name, "texture " + texture.name + " needs a ResourceName annotation (or ': RENDERCOLORTARGET')");
        add_texture(std::move(texture), name);
    }

    void check_default(Parameter& parameter, const Token& first) {
        Value& value = *parameter.default_value;
        const int needed = component_count(parameter.type) * std::max(1, parameter.array_size);
        if (value.is_string) fail(first, "default of " + parameter.name + " must be numeric, not a string");
        if (needed == 0) fail(first, parameter.type + " " + parameter.name + " takes no default value");
        if (value.numbers.size() == 1 && needed > 1 && parameter.array_size == 0 && parameter.type.rfind("mat", 0) != 0)
            value.numbers.assign(static_cast<size_t>(needed), value.numbers[0]);  // vec3(0.5) broadcasts
        if (static_cast<int>(value.numbers.size()) != needed)
            fail(first, "default of " + parameter.type + " " + parameter.name + " has " + std::to_string(value.numbers.size()) +
                            " value(s), needs " + std::to_string(needed));
        const bool integral = parameter.type == "int" || parameter.type.rfind("ivec", 0) == 0;
        for (double v : value.numbers)
            if (integral && (v != std::floor(v) || v < -2147483648.0 || v > 2147483647.0))
                fail(first, "default of " + parameter.type + " " + parameter.name + " must be whole numbers a 32-bit int holds");
    }

    void parse_shader_block() {
        next();  // GLSLShader
        const Token name = expect_identifier("a shader name");
        if (shader_index_.count(name.text)) fail(name, "shader '" + name.text + "' defined twice");
        count_declaration(name, shader_index_.size(), "shader blocks");
        shader_index_.emplace(name.text, effect_.shaders.size());
        const Token open = expect('{', "to open shader " + name.text);
        const Token close = skip_block(open, "shader " + name.text);
        ShaderBlock block;
        block.name = name.text;
        block.code = effect_.sources.glsl(open.end, close.begin);
        block.where = at(name);
        effect_.shaders.push_back(std::move(block));
    }

    // plugin NAME < string Type = "..."; ... >;
    void parse_plugin() {
        next();  // plugin
        PluginDeclaration plugin;
        const Token name = expect_identifier("a plugin name");
        plugin.name = name.text;
        plugin.where = at(name);
        if (effect_.find_plugin(plugin.name)) fail(name, "plugin '" + plugin.name + "' defined twice");
        if (effect_.plugins.size() >= kMaxPlugins) fail(name, "more than " + std::to_string(kMaxPlugins) + " plugins in one effect");
        plugin.annotations = parse_annotations();
        expect(';', "after the declaration of plugin " + plugin.name);
        const Annotation* type = plugin.find("Type");
        if (!type) fail(name, "plugin " + plugin.name + " needs a Type annotation (string Type = \"brdf-fit\")");
        if (!type->value.is_string) fail(name, "plugin " + plugin.name + ": Type must be a string");
        effect_.plugins.push_back(std::move(plugin));
    }

    void parse_technique() {
        next();  // technique
        Technique technique;
        const Token name = expect_identifier("a technique name");
        technique.name = name.text;
        technique.where = at(name);
        if (!technique_names_.insert(technique.name).second) fail(name, "technique '" + technique.name + "' defined twice");
        if (technique_names_.size() > kMaxTechniques)
            fail(name, "more than " + std::to_string(kMaxTechniques) + " techniques in one effect");
        technique.annotations = parse_annotations();
        const Token open = expect('{', "to open technique " + technique.name);
        while (!accept('}')) {
            const Token keyword = next();
            if (keyword.kind == TokenKind::End) fail(open, "unterminated technique " + technique.name + ": '{' is never closed");
            if (keyword.kind != TokenKind::Identifier || keyword.text != "pass")
                fail(keyword, "expected 'pass' or '}' in technique " + technique.name + ", found '" + keyword.text + "'");
            if (++pass_count_ > kMaxPasses) fail(keyword, "more than " + std::to_string(kMaxPasses) + " passes in one effect");
            technique.passes.push_back(parse_pass(technique));
        }
        if (technique.passes.empty()) fail(name, "technique " + technique.name + " has no pass");
        effect_.techniques.push_back(std::move(technique));
    }

    Pass parse_pass(const Technique& technique) {
        Pass pass;
        Token token = lexer_.peek();
        pass.where = at(token);
        pass.name = token.kind == TokenKind::Identifier ? next().text : "p" + std::to_string(technique.passes.size());
        for (const auto& other : technique.passes)
            if (other.name == pass.name) fail(token, "pass '" + pass.name + "' defined twice in technique " + technique.name);
        parse_annotations();
        const Token open = expect('{', "to open pass " + pass.name);
        while (!accept('}')) {
            const Token state = next();
            if (state.kind == TokenKind::End) fail(open, "unterminated pass " + pass.name + ": '{' is never closed");
            if (state.kind != TokenKind::Identifier) fail(state, "expected a state name in pass " + pass.name + ", found '" + state.text + "'");
            expect('=', "after " + state.text);
            const std::string key = to_lower(state.text);
            static const std::map<std::string, ShaderStage> stages = {
                {"vertexshader", ShaderStage::Vertex},     {"vertexprogram", ShaderStage::Vertex},
                {"fragmentshader", ShaderStage::Fragment}, {"fragmentprogram", ShaderStage::Fragment},
                {"pixelshader", ShaderStage::Fragment},    {"geometryshader", ShaderStage::Geometry},
                {"geometryprogram", ShaderStage::Geometry}};
            if (const auto stage = stages.find(key); stage != stages.end()) {
                Token shader = expect_identifier("a shader name");
                if (shader.text == "compile") {  // CgFX: compile PROFILE name(...)
                    expect_identifier("a profile after 'compile'");
                    shader = expect_identifier("a shader name");
                    if (accept('(')) expect(')', "after the shader name");
                }
                pass.shaders[stage->second] = shader.text;
                shader_uses_.push_back({shader, stage->second});
            } else {
                set_render_state(pass.states, state.text, parse_state_value(), at(state));
            }
            expect(';', "after the value of " + state.text);
        }
        if (!pass.shaders.count(ShaderStage::Vertex) || !pass.shaders.count(ShaderStage::Fragment))
            throw EffectError(pass.where, "pass " + pass.name + " needs a VertexShader and a FragmentShader");
        return pass;
    }

    StateValue parse_state_value() {
        StateValue value;
        const bool grouped = accept('(') ? true : false;
        const bool braced = !grouped && accept('{');
        do {
            Token token = next();
            bool negative = false;
            if (token.kind == TokenKind::Punct && token.text == "-") {
                negative = true;
                token = next();
            }
            if (token.kind == TokenKind::Number) {
                value.numbers.push_back(parse_number(token, negative));
                value.is_number.push_back(true);
            } else if (token.kind == TokenKind::Identifier && !negative) {
                value.words.push_back(token.text);
                value.is_number.push_back(false);
            } else {
                fail(token, "expected a state value, found " + (token.kind == TokenKind::End ? "end of file" : "'" + token.text + "'"));
            }
        } while ((grouped || braced) && accept(','));
        if (grouped) expect(')', "to close the state value");
        if (braced) expect('}', "to close the state value");
        return value;
    }

    // Functions, structs, consts and anything else GLSL: copied to every stage unchanged.
    void parse_glsl_declaration() {
        const Token first = next();
        if (first.kind == TokenKind::Punct && first.text == "}") fail(first, "unexpected '}'");
        size_t end = first.end;
        if (!(first.kind == TokenKind::Punct && first.text == ";")) {
            for (;;) {
                const Token token = next();
                if (token.kind == TokenKind::End) fail(first, "declaration starting with '" + first.text + "' never ends (missing ';' or '}')");
                // Effect keywords never occur inside a GLSL declaration: a ';' is missing before them.
                if (token.kind == TokenKind::Identifier && (token.text == "technique" || token.text == "GLSLShader"))
                    fail(token, "expected ';' before '" + token.text + "' (the declaration starting with '" + first.text + "' at " +
                                    at(first).str() + " is not finished)");
                end = token.end;
                if (token.kind != TokenKind::Punct) continue;
                if (token.text == ";") break;
                if (token.text == "{") {
                    end = skip_block(token, "block").end;
                    if (lexer_.peek().text == ";") end = next().end;  // struct S { ... };
                    break;
                }
            }
        }
        effect_.globals += effect_.sources.glsl(first.begin, end);
    }

    void check_references() {
        if (effect_.techniques.empty())
            throw EffectError({effect_.path, 1}, "the effect defines no technique");
        for (const auto& [token, stage] : shader_uses_)
            if (!shader_index_.count(token.text)) fail(token, "unknown shader '" + token.text + "'");
        for (const auto& [token, name] : texture_uses_)
            if (!texture_index_.count(name)) fail(token, "unknown texture '" + name + "'");
        for (const auto& p : effect_.parameters)
            if (!p.ui.at_least.empty()) {
                const auto other = parameter_index_.find(p.ui.at_least);
                if (other == parameter_index_.end() || component_count(effect_.parameters[other->second].type) != 1 ||
                    component_count(p.type) != 1 || p.array_size > 0)
                    throw EffectError(p.where, "UIAtLeast of " + p.name + " must name another scalar parameter, not '" +
                                                   excerpt(p.ui.at_least) + "'");
            }
        for (const auto& p : effect_.parameters)
            if (is_sampler_type(p.type) && !p.texture.empty() && !texture_index_.count(p.texture))
                throw EffectError(p.where, "sampler " + p.name + " reads unknown texture '" + p.texture + "'");
        // Every pass compiles the top-level GLSL with its shaders; drivers take seconds per megabyte.
        std::int64_t compiled = 0;
        for (const auto& technique : effect_.techniques)
            for (const auto& pass : technique.passes) {
                compiled += static_cast<std::int64_t>(effect_.globals.size()) * static_cast<std::int64_t>(pass.shaders.size());
                for (const auto& [stage, name] : pass.shaders)
                    compiled += static_cast<std::int64_t>(effect_.shaders[shader_index_.at(name)].code.size());
                if (compiled > effect_.limits.compile_bytes)
                    throw EffectError(pass.where, "technique " + technique.name + " brings the GLSL compiled for this effect to " +
                                                      std::to_string(compiled) + " bytes, over the budget compile-bytes = " +
                                                      std::to_string(effect_.limits.compile_bytes) + " (raise it with --limit compile-bytes=N)");
            }
        for (const auto& technique : effect_.techniques)
            for (const auto& pass : technique.passes)
                for (const auto& target : pass.states.render_targets) {
                    const auto found = texture_index_.find(target);
                    const TextureResource* texture = found == texture_index_.end() ? nullptr : &effect_.textures[found->second];
                    if (target.empty()) throw EffectError(pass.where, "pass " + pass.name + " leaves a gap in its render targets");
                    if (!texture || !texture->render_target)
                        throw EffectError(pass.where, "pass " + pass.name + " renders into '" + target +
                                                          "', which is not declared as texture " + target + " : RENDERCOLORTARGET");
                }
    }

    // Fixed caps far above any real effect: they keep checks and GLSL compiles of a hostile file short.
    // Each pass is a GLSL program to compile: their number bounds how long `check` can take.
    static constexpr size_t kMaxDeclarations = 4096, kMaxTechniques = 256, kMaxPasses = 256, kMaxPlugins = 64;
    size_t pass_count_ = 0;
    void count_declaration(const Token& name, size_t declared, const char* what) const {
        if (declared >= kMaxDeclarations) fail(name, "more than " + std::to_string(kMaxDeclarations) + " " + what + " in one effect");
    }

    Effect& effect_;
    // Names seen so far, for duplicate and reference checks that stay fast with many declarations.
    std::unordered_map<std::string, size_t> parameter_index_, texture_index_, shader_index_;
    std::unordered_set<std::string> technique_names_;
    std::vector<std::pair<Token, ShaderStage>> shader_uses_;
    std::vector<std::pair<Token, std::string>> texture_uses_;
};

}  // namespace

Effect load_effect(const std::string& path, const LoadOptions& options) {
    Effect effect;
    effect.path = path;
    effect.limits = options.limits;
    effect.access = options.access;
    for (const auto& dir : options.include_dirs) effect.access.allow_folder(dir);  // search roots are readable
    effect.access.allow_folder(std::filesystem::path(path).parent_path().empty() ? std::filesystem::path(".")
                                                                                 : std::filesystem::path(path).parent_path());
    effect.sources = SourceMap::load(path, options.include_dirs, effect.limits, effect.access);
    if (legacy::is_legacy_effect(effect)) legacy::load_legacy_effect(effect, options.matrix_convention);
    else Parser(effect).parse();
    std::vector<std::string> warnings = effect.sources.warnings();  // the translated file's first
    warnings.insert(warnings.end(), effect.warnings.begin(), effect.warnings.end());
    effect.warnings = std::move(warnings);
    for (auto& parameter : effect.parameters)
        if (parameter.ui.items.size() == 1)
            if (const auto list = options.item_lists.find(parameter.ui.items[0]); list != options.item_lists.end())
                parameter.ui.items = list->second;
    check_defaults(effect);
    return effect;
}

}  // namespace fxview::effect
