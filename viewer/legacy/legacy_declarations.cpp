#include <algorithm>
#include <charconv>
#include <cmath>
#include <set>

#include "core/text.hpp"
#include "effect/texture_annotations.hpp"
#include "legacy/legacy_parser.hpp"
#include "legacy/legacy_states.hpp"

namespace fxview::legacy {

bool LegacyParser::is_dx10_state_object(const std::string& word) {
    const std::string w = to_lower(word);
    return w == "rasterizerstate" || w == "depthstencilstate" || w == "blendstate" || w == "samplerstate" || w == "samplercomparisonstate";
}

// DirectX 10 `RasterizerState NAME { ... };` and kin: only DX10 techniques use them. A
// SamplerState keeps its declaration (DX10 functions may name it) without the state block.
void LegacyParser::parse_dx10_state_object() {
    const Token type = next();
    const Token name = expect_identifier("a name after " + type.text);
    if (is(peek(), "[")) skip_balanced(next());
    const bool sampler = to_lower(type.text).rfind("sampler", 0) == 0;
    const size_t block = peek().begin;
    if (is(peek(), "{")) skip_balanced(next());
    else if (is(peek(), "=") ) { next(); parse_value({";"}); }
    expect(";", "after " + type.text + " " + name.text);
    if (sampler) blank(block, last_end_ - 1);
    else blank(type.begin, last_end_);
}

void LegacyParser::parse_string_global() {
    const Token first = next();
    const Token name = expect_identifier("a name after 'string'");
    if (accept(":")) next();
    parse_annotations();
    if (accept("=")) parse_value({";"});
    expect(";", "after string " + name.text);
    blank(first.begin, last_end_);
}

void LegacyParser::parse_texture() {
    const Token keyword = next();
    parse_texture_after(keyword, keyword.begin);
}

// The rest of `[uniform] texture NAME ...;` once its keyword is read; the declaration from `begin` is blanked.
void LegacyParser::parse_texture_after(const Token& keyword, size_t begin) {
    effect::TextureResource texture;
    const Token name = expect_identifier("a texture name");
    texture.name = name.text;
    texture.where = at(name);
    const std::string kind = to_lower(keyword.text);
    texture.type = kind == "texture3d" ? texture::TextureType::Tex3D
                 : kind == "texturecube" ? texture::TextureType::Cube
                 : kind == "texture1d" ? texture::TextureType::Tex1D
                                       : texture::TextureType::Tex2D;
    std::string semantic;
    if (accept(":")) semantic = to_lower(expect_identifier("a semantic").text);
    const auto annotations = parse_annotations();
    if (accept("=")) parse_value({";"});
    expect(";", "after texture " + texture.name);
    blank(begin, last_end_);
    if (semantic == "renderdepthstenciltarget") return;  // every pass target has its own depth buffer
    texture.render_target = semantic == "rendercolortarget";
    for (const auto& a : annotations)
        if (to_lower(a.name) == "resourcetype" && a.value.is_string) {
            const std::string t = to_lower(a.value.text);
            if (t == "cube") texture.type = texture::TextureType::Cube;
            if (t == "3d" || t == "volume") texture.type = texture::TextureType::Tex3D;
        }
    std::vector<effect::Annotation> usable;
    for (const auto& a : annotations) {
        const std::string key = to_lower(a.name);
        if (key == "format") {
            if (a.value.is_string) texture.storage = storage_from_format(a.value.text);
        } else if (key == "resourcename" || key == "viewportratio" || key == "dimensions" || key == "colorspace") {
            usable.push_back(a);
        } else if ((key == "name" || key == "file") && a.value.is_string && !a.value.text.empty()) {
            effect::Annotation file = a;  // DirectX 8/9 SDK effects: string name = "file.dds"
            file.name = "ResourceName";
            usable.push_back(file);
        }
    }
    effect::apply_texture_annotations(texture, usable);
    if (texture.render_target) texture.files.clear();
    texture.annotations = annotations;
    source_.textures.push_back(std::move(texture));
}

// TYPE NAME [N] [: SEMANTIC] [<annotations>] [= value | = sampler_state { ... }] ; or a function.
void LegacyParser::parse_declaration() {
    const Token first = peek();
    bool is_static = false;
    std::vector<Token> words;
    while (peek().kind == TokenKind::Identifier && kQualifiers.count(peek().text)) {
        const Token q = next();
        if (q.text == "static" || q.text == "const") is_static = true;
        words.push_back(q);
    }
    const Token type = next();
    if (type.kind != TokenKind::Identifier) fail(type, "unexpected '" + excerpt(type.text) + "' at the top level");
    if (is_texture_keyword(type.text)) {  // CgFX: uniform texture2D NAME < ... >;
        parse_texture_after(type, first.begin);
        return;
    }
    if (is(peek(), "<")) {  // vector<float, 4>, matrix<float, 4, 4>
        const Token open = next();
        while (!accept(">"))
            if (next().kind == TokenKind::End) fail(open, "'<' is never closed");
    }
    const Token name = next();
    if (name.kind != TokenKind::Identifier)
        fail(name, "expected a name after '" + excerpt(type.text) + "', found '" + excerpt(name.text) + "'" +
                       (type.text == "struct" ? " (of Cg 3 buffer blocks fxview reads plain members: uniform struct { TYPE name; ... } VAR : BUFFER[n];)" : ""));
    if (is(peek(), "(")) {
        parse_function(type, name);
        return;
    }
    bool dropped = false;
    for (Token declarator = name;;) {
        dropped = !parse_variable(type, declarator, is_static) || dropped;
        if (accept(",")) {
            declarator = expect_identifier("a name after ','");
            continue;
        }
        expect(";", "after the declaration of " + declarator.text);
        if (dropped) blank(first.begin, last_end_);
        return;
    }
}

// Returns false for a declaration that is no shader variable (the SAS STANDARDSGLOBAL).
bool LegacyParser::parse_variable(const Token& type, const Token& name, bool is_static) {
    LegacyGlobal global;
    global.type = type.text;
    global.name = name.text;
    global.where = at(name);
    // HLSL refuses a second declaration of a name, and glslang crashes on some (a float4 and a float
    // of one name grow its global block inconsistently): said here, at the second one.
    if (const auto [first, added] = declared_.emplace(name.text, global.where); !added)
        fail(name, "'" + excerpt(name.text) + "' is declared twice (first at " + first->second.str() + ")");
    if (is(peek(), "[")) {
        const Token open = next();
        const Token size = next();
        const auto n = size.kind == TokenKind::Number ? number_of(size, false) : std::nullopt;
        if (!n || *n < 1 || *n != std::floor(*n) || *n > static_cast<double>(effect_.limits.array_elements))
            fail(size, "array size of " + name.text + " must be a whole number from 1 to " + std::to_string(effect_.limits.array_elements));
        global.array_size = static_cast<int>(*n);
        if (!accept("]")) skip_balanced(open);
    }
    if (is(peek(), ":")) {
        next();
        const Token semantic = expect_identifier("a semantic after ':'");
        if (semantic.text == "register" && is(peek(), "(")) skip_balanced(next());
        else global.semantic = semantic.text;
    }
    if (is(peek(), "<")) {
        const size_t begin = peek().begin;
        global.annotations = parse_annotations();
        blank(begin, last_end_);
    }
    const bool sampler = to_lower(global.type).rfind("sampler", 0) == 0;
    if (is(peek(), "=")) {
        const size_t begin = peek().begin;
        next();
        if (is(peek(), "sampler_state") || (sampler && is(peek(), "{"))) {
            if (is(peek(), "sampler_state")) next();
            parse_sampler_state(global);
            blank(begin, last_end_);
        } else if (is_static) {
            parse_value({";", ","});  // a constant stays in the code as written
        } else {
            const Token first = peek();
            global.default_value = parse_value({";", ","});
            if (!global.default_value)
                source_.warnings.push_back(at(first).str() + ": warning: the default of " + global.name +
                                           " is an expression fxview does not evaluate (numbers, + - * / and constructors are); it starts at 0");
            blank(begin, last_end_);
        }
    }
    for (const auto& a : global.annotations)
        if (to_lower(a.name) == "texture" && a.value.is_string) global.texture = a.value.text;
    // DX9's untyped sampler: typed at the end, from its texture or from how the code samples it.
    if (sampler && global.type == "sampler" && !is_static) untyped_.push_back({type.begin, type.end, source_.globals.size()});
    if (is_matrix_type(global.type)) {
        matrices_.insert(global.name);
        // A matrix bound transposed (WorldViewProjectionTranspose, not the normal matrices'
        // InverseTranspose) multiplies the other way round: mul(v, Mᵀ) is mul(M, v).
        const std::string semantic = to_lower(global.semantic);
        if (semantic.size() > 9 && semantic.ends_with("transpose") && !semantic.ends_with("inversetranspose")) transposed_.insert(global.name);
    }
    if (is_static) return true;
    if (source_.globals.size() >= kMaxGlobals) fail(name, "more than " + std::to_string(kMaxGlobals) + " parameters in one effect");
    if (to_lower(global.semantic) == "standardsglobal") {  // `float Script : STANDARDSGLOBAL` is no parameter
        source_.effect_annotations = global.annotations;
        return false;
    }
    source_.globals.push_back(std::move(global));
    return true;
}

effect::TextureResource* LegacyParser::find_texture(const std::string& name) {
    for (auto& t : source_.textures)
        if (t.name == name) return &t;
    return nullptr;
}

// Whether the code calls FUNCTION(NAME ...) (blanks allowed around the parenthesis).
bool LegacyParser::sampled_with(const std::string& function, const std::string& name) const {
    for (size_t at = text_.find(function); at != std::string::npos; at = text_.find(function, at + 1)) {
        size_t i = at + function.size();
        if (i < text_.size() && (std::isalnum(static_cast<unsigned char>(text_[i])) || text_[i] == '_')) continue;  // texCUBEbias is also fine below
        while (i < text_.size() && text_[i] == ' ') ++i;
        if (i >= text_.size() || text_[i] != '(') continue;
        ++i;
        while (i < text_.size() && text_[i] == ' ') ++i;
        if (text_.compare(i, name.size(), name) == 0 &&
            (i + name.size() >= text_.size() || !(std::isalnum(static_cast<unsigned char>(text_[i + name.size()])) || text_[i + name.size()] == '_')))
            return true;
    }
    return false;
}

void LegacyParser::type_untyped_samplers() {
    for (const auto& u : untyped_) {
        LegacyGlobal& global = source_.globals[u.global];
        effect::TextureResource* texture = find_texture(global.texture);
        texture::TextureType type = texture ? texture->type : texture::TextureType::Tex2D;
        if (type == texture::TextureType::Tex2D) {
            for (const char* f : {"texCUBE", "texCUBEproj", "texCUBElod", "texCUBEbias"})
                if (sampled_with(f, global.name)) type = texture::TextureType::Cube;
            for (const char* f : {"tex3D", "tex3Dproj", "tex3Dlod", "tex3Dbias"})
                if (sampled_with(f, global.name)) type = texture::TextureType::Tex3D;
            for (const char* f : {"tex1D", "tex1Dproj", "tex1Dlod"})
                if (sampled_with(f, global.name)) type = texture::TextureType::Tex1D;
            if (texture) texture->type = type;
        }
        const char* typed = type == texture::TextureType::Cube ? "samplerCUBE"
                          : type == texture::TextureType::Tex3D ? "sampler3D"
                          : type == texture::TextureType::Tex1D ? "sampler1D"
                                                                 : "sampler2D";
        replace(u.begin, u.end, typed);
        global.type = typed;
    }
}

void LegacyParser::parse_sampler_state(LegacyGlobal& global) {
    const Token open = expect("{", "to open sampler_state");
    while (!accept("}")) {
        const Token state = next();
        if (state.kind == TokenKind::End) fail(open, "unterminated sampler_state: '{' is never closed");
        if (state.kind != TokenKind::Identifier) fail(state, "expected a sampler state name, found '" + excerpt(state.text) + "'");
        expect("=", "after " + state.text);
        std::vector<Token> value;
        while (!is(peek(), ";") && !is(peek(), "}")) {
            const Token t = next();
            if (t.kind == TokenKind::End) fail(open, "unterminated sampler_state");
            if (t.kind == TokenKind::Identifier || t.kind == TokenKind::Number) value.push_back(t);
        }
        accept(";");
        if (value.empty()) continue;
        const std::string key = to_lower(state.text);
        if (key == "texture") {
            global.texture = value.front().text;
            continue;
        }
        set_legacy_sampler_state(global.sampler, state.text, value.front().text, at(state), source_.warnings, warned_);
    }
}

// --- functions ----------------------------------------------------------------------------
void LegacyParser::parse_function(const Token& type, const Token& name) {
    FunctionSignature function;
    function.name = name.text;
    function.return_type = type.text;
    function.where = at(name);
    const Token open = next();  // (
    std::vector<Token> parameter;
    auto finish_parameter = [&]() {
        if (parameter.empty()) return;
        FunctionParameter p;
        size_t i = 0;
        for (; i < parameter.size() && kQualifiers.count(parameter[i].text); ++i) {
            if (parameter[i].text == "uniform") {
                p.uniform = true;
                blank(parameter[i].begin, parameter[i].end);
            }
        }
        if (i + 1 < parameter.size()) {
            p.type = parameter[i].text;
            p.name = parameter[i + 1].text;
            if (is_matrix_type(p.type)) matrices_.insert(p.name);
        }
        for (size_t k = 0; k < parameter.size(); ++k) {
            if (parameter[k].text == "out" || parameter[k].text == "inout") p.output = true;
            if (is(parameter[k], ":") && k + 1 < parameter.size()) p.semantic = parameter[k + 1].text;
        }
        size_t end = parameter.back().end;
        for (size_t k = 0; k < parameter.size(); ++k)
            if (is(parameter[k], "=")) {  // a default value (Cg): not part of the wrapper's declaration
                end = parameter[k].begin;
                break;
            }
        for (size_t k = 0; k < parameter.size() && parameter[k].begin < end; ++k) {
            if (parameter[k].text == "uniform" && parameter[k].kind == TokenKind::Identifier) continue;
            p.declaration += (p.declaration.empty() ? "" : " ") + text_.substr(parameter[k].begin, parameter[k].end - parameter[k].begin);
        }
        if (p.name.empty() && p.type != "void") fail(parameter.front(), "parameter without a name in " + function.name);
        if (!p.name.empty()) function.parameters.push_back(std::move(p));
        parameter.clear();
    };
    for (int depth = 1; depth > 0;) {
        const Token t = next();
        if (t.kind == TokenKind::End) fail(open, "the parameter list of " + function.name + " is never closed");
        if (is(t, "(") || is(t, "[")) ++depth;
        if (is(t, ")") || is(t, "]")) --depth;
        if (depth == 0) break;
        if (depth == 1 && is(t, ",")) {
            finish_parameter();
            continue;
        }
        parameter.push_back(t);
    }
    finish_parameter();
    if (accept(":")) function.return_semantic = ": " + expect_identifier("a semantic").text;
    const Token body = next();
    if (is(body, ";")) return;  // a prototype
    if (!is(body, "{")) fail(body, "expected the body of " + function.name + ", found '" + excerpt(body.text) + "'");
    count_mul_uses(body);
    source_.functions.emplace(function.name, std::move(function));
}

// Counts mul(M, x) and mul(x, M) for matrix-typed names M inside a function body (consumed).
void LegacyParser::count_mul_uses(const Token& open) {
    std::vector<Token> body;
    for (int depth = 1; depth > 0;) {
        const Token t = next();
        if (t.kind == TokenKind::End) fail(open, "function body is never closed");
        if (is(t, "{")) ++depth;
        if (is(t, "}")) --depth;
        body.push_back(t);
    }
    std::set<std::string> local = matrices_;
    for (size_t i = 0; i + 1 < body.size(); ++i)
        if (body[i].kind == TokenKind::Identifier && is_matrix_type(body[i].text) && body[i + 1].kind == TokenKind::Identifier)
            local.insert(body[i + 1].text);
    auto is_matrix_argument = [&](size_t i) {  // M, (float3x3)M, M[0]? no: a row is a vector
        if (i >= body.size()) return false;
        if (body[i].kind == TokenKind::Identifier) return local.count(body[i].text) > 0 && !(i + 1 < body.size() && (is(body[i + 1], "[") || is(body[i + 1], ".")));
        if (is(body[i], "(") && i + 2 < body.size() && is_matrix_type(body[i + 1].text) && is(body[i + 2], ")")) return true;
        return false;
    };
    for (size_t i = 0; i + 2 < body.size(); ++i) {
        if (!(body[i].kind == TokenKind::Identifier && body[i].text == "mul" && is(body[i + 1], "("))) continue;
        size_t comma = i + 2;
        for (int depth = 0; comma < body.size(); ++comma) {
            if (is(body[comma], "(") || is(body[comma], "[")) ++depth;
            if (is(body[comma], ")") || is(body[comma], "]")) { if (depth == 0) break; --depth; }
            if (depth == 0 && is(body[comma], ",")) break;
        }
        if (comma >= body.size() || !is(body[comma], ",")) continue;
        const bool first_matrix = is_matrix_argument(i + 2), second_matrix = is_matrix_argument(comma + 1);
        const auto transposed = [&](size_t k) { return body[k].kind == TokenKind::Identifier && transposed_.count(body[k].text) > 0; };
        if (first_matrix && !second_matrix) ++(transposed(i + 2) ? source_.row_vector_uses : source_.column_vector_uses);
        if (second_matrix && !first_matrix) ++(transposed(comma + 1) ? source_.column_vector_uses : source_.row_vector_uses);
    }
}

}  // namespace fxview::legacy
