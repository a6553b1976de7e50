#include <algorithm>
#include <charconv>
#include <cmath>
#include <set>

#include "core/text.hpp"
#include "effect/lexer.hpp"
#include "effect/texture_annotations.hpp"
#include "legacy/legacy_source.hpp"
#include "legacy/legacy_states.hpp"

namespace fxview::legacy {
namespace {

using effect::Token;
using effect::TokenKind;

bool is_matrix_type(const std::string& type) {
    // float4x4, half3x3, fixed2x2, double4x3, int3x3, matrix
    if (type == "matrix") return true;
    const size_t x = type.size() >= 3 ? type.size() - 2 : std::string::npos;
    return x != std::string::npos && type[x] == 'x' && std::isdigit(static_cast<unsigned char>(type[x - 1])) &&
           std::isdigit(static_cast<unsigned char>(type[x + 1]));
}

const std::set<std::string> kQualifiers = {"static", "const", "uniform", "extern", "shared", "volatile", "row_major",
                                           "column_major", "inline", "precise", "groupshared", "nointerpolation", "in",
                                           "out", "inout", "linear", "centroid", "noperspective", "sample"};

class LegacyParser {
public:
    explicit LegacyParser(const effect::Effect& effect) : effect_(effect), text_(effect.sources.text()), lexer_(text_) {}

    LegacySource parse() {
        for (;;) {
            const Token token = peek();
            if (token.kind == TokenKind::End) break;
            if (token.kind == TokenKind::Preprocessor) {
                next();  // #pragma and the like stay in the code
            } else if (token.kind == TokenKind::Punct && token.text == ";") {
                next();
            } else if (token.kind == TokenKind::Identifier && (token.text == "technique" || token.text == "technique9")) {
                parse_technique();
            } else if (token.kind == TokenKind::Identifier && (token.text == "technique10" || token.text == "technique11")) {
                const Token keyword = next();
                const Token name = next();
                skip_to_block_end(keyword);
                blank(keyword.begin, last_end_);
                source_.warnings.push_back(at(keyword).str() + ": warning: " + keyword.text + " " + name.text +
                                           " skipped (DirectX 10/11 techniques are not supported; the DX9 techniques load)");
            } else if (token.kind == TokenKind::Identifier && token.text == "interface") {
                fail(token, "Cg interfaces are not supported");
            } else if (token.kind == TokenKind::Identifier && token.text == "struct") {
                skip_declaration();
            } else if (token.kind == TokenKind::Identifier && (token.text == "typedef" || token.text == "cbuffer" || token.text == "tbuffer")) {
                skip_declaration();
            } else if (token.kind == TokenKind::Identifier && is_dx10_state_object(token.text)) {
                parse_dx10_state_object();
            } else if (token.kind == TokenKind::Identifier && to_lower(token.text) == "string") {
                parse_string_global();
            } else if (token.kind == TokenKind::Identifier && is_texture_keyword(token.text)) {
                parse_texture();
            } else if (token.kind == TokenKind::Identifier &&
                       (token.text == "VertexShader" || token.text == "PixelShader" || token.text == "vertexshader" ||
                        token.text == "pixelshader")) {
                fail(token, "shader variables (" + token.text + " name = compile ...) are not supported; write the compile statement in the pass");
            } else {
                parse_declaration();
            }
        }
        type_untyped_samplers();
        source_.code = apply_edits();
        return std::move(source_);
    }

private:
    // --- tokens -------------------------------------------------------------------------------
    Token next() {
        Token token = lexer_.next();
        if (lexer_.unterminated != std::string_view::npos)
            throw effect::EffectError(effect_.sources.locate(lexer_.unterminated), "unterminated comment or string");
        last_end_ = token.end;
        return token;
    }
    Token peek() { return lexer_.peek(); }
    bool is(const Token& t, const char* text) const { return t.text == text && t.kind != TokenKind::String; }
    bool accept(const char* text) {
        if (is(peek(), text)) {
            next();
            return true;
        }
        return false;
    }
    effect::SourceLocation at(const Token& t) const { return effect_.sources.locate(t.begin); }
    [[noreturn]] void fail(const Token& t, const std::string& message) const { throw effect::EffectError(at(t), excerpt(message, 400)); }
    Token expect(const char* text, const std::string& context) {
        const Token token = next();
        if (!is(token, text))
            fail(token, std::string("expected '") + text + "' " + context + ", found " +
                            (token.kind == TokenKind::End ? "end of file" : "'" + excerpt(token.text) + "'"));
        return token;
    }
    Token expect_identifier(const std::string& what) {
        const Token token = next();
        if (token.kind != TokenKind::Identifier)
            fail(token, "expected " + what + ", found " + (token.kind == TokenKind::End ? "end of file" : "'" + excerpt(token.text) + "'"));
        return token;
    }
    // After an opening token has been read: to the matching close of ( [ { (the close is consumed).
    void skip_balanced(const Token& open) {
        int depth = 1;
        while (depth > 0) {
            const Token t = next();
            if (t.kind == TokenKind::End) fail(open, "'" + open.text + "' is never closed");
            if (t.kind != TokenKind::Punct) continue;
            if (t.text == "(" || t.text == "[" || t.text == "{") ++depth;
            if (t.text == ")" || t.text == "]" || t.text == "}") --depth;
        }
    }
    void skip_to_block_end(const Token& first) {
        for (;;) {
            const Token t = next();
            if (t.kind == TokenKind::End) fail(first, "'" + first.text + "' block never ends");
            if (is(t, "{")) {
                skip_balanced(t);
                accept(";");
                return;
            }
        }
    }
    // A declaration kept as code: to its ';' at depth 0, or through its block and an optional ';'.
    void skip_declaration() {
        const Token first = next();
        for (;;) {
            const Token t = next();
            if (t.kind == TokenKind::End) fail(first, "declaration starting with '" + excerpt(first.text) + "' never ends (missing ';' or '}')");
            if (is(t, ";")) return;
            if (is(t, "{")) {
                skip_balanced(t);
                if (first.text != "struct" && first.text != "cbuffer" && first.text != "tbuffer") return;
            }
            if (is(t, "(")) skip_balanced(t);
        }
    }

    // --- edits of the code: blanked spans keep their newlines ---------------------------------
    void blank(size_t begin, size_t end) { edits_.push_back({begin, end, newlines(begin, end)}); }
    void replace(size_t begin, size_t end, std::string with) { edits_.push_back({begin, end, std::move(with)}); }
    std::string newlines(size_t begin, size_t end) const {
        return std::string(static_cast<size_t>(std::count(text_.begin() + static_cast<long>(begin), text_.begin() + static_cast<long>(end), '\n')), '\n');
    }
    std::string apply_edits() {
        // An edit inside another (an annotation inside a blanked declaration) gives way to the outer one.
        std::sort(edits_.begin(), edits_.end(), [](const Edit& a, const Edit& b) { return a.begin != b.begin ? a.begin < b.begin : a.end > b.end; });
        std::vector<Edit> kept;
        for (auto& e : edits_)
            if (kept.empty() || e.begin >= kept.back().end) kept.push_back(std::move(e));
        std::string code = text_;
        for (auto it = kept.rbegin(); it != kept.rend(); ++it) code.replace(it->begin, it->end - it->begin, it->with);
        return code;
    }

    // --- values and annotations ---------------------------------------------------------------
    std::optional<double> number_of(const Token& token, bool negative) const {
        std::string text = token.text;
        while (!text.empty() && std::string("fFhHuUlL").find(text.back()) != std::string::npos) text.pop_back();
        double value = 0;
        const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
        if (error != std::errc() || end != text.data() + text.size()) return std::nullopt;
        return negative ? -value : value;
    }
    // A constant: 1.5, -2, true, "text" "more", {1, 2}, float3(1, 2, 3); nullopt (tokens consumed
    // up to `stop`) for an expression this reader does not evaluate.
    std::optional<effect::Value> parse_value(const std::set<std::string>& stops) {
        effect::Value value;
        Token t = peek();
        if (t.kind == TokenKind::String) {
            value.is_string = true;
            while (peek().kind == TokenKind::String) value.text += next().text;
            return value;
        }
        bool ok = true;
        int depth = 0;
        bool negative = false;
        for (;;) {
            t = peek();
            if (t.kind == TokenKind::End) fail(t, "value never ends");
            if (depth == 0 && t.kind == TokenKind::Punct && stops.count(t.text)) break;
            next();
            if (is(t, "{") || is(t, "(")) { ++depth; continue; }
            if (is(t, "}") || is(t, ")")) { --depth; continue; }
            if (is(t, ",")) continue;
            if (is(t, "-")) { negative = !negative; continue; }
            if (is(t, "+")) continue;
            if (t.kind == TokenKind::Number) {
                if (const auto v = number_of(t, negative)) value.numbers.push_back(*v);
                else ok = false;
            } else if (t.kind == TokenKind::Identifier && (t.text == "true" || t.text == "false")) {
                value.numbers.push_back(t.text == "true" ? 1.0 : 0.0);
            } else if (t.kind == TokenKind::Identifier && is(peek(), "(")) {
                // a constructor such as float3( ... ): its numbers follow
            } else {
                ok = false;
            }
            negative = false;
        }
        if (!ok || value.numbers.empty()) return std::nullopt;
        return value;
    }
    std::vector<effect::Annotation> parse_annotations() {
        std::vector<effect::Annotation> annotations;
        const Token open = peek();
        if (!accept("<")) return annotations;
        while (!accept(">")) {
            const Token type = expect_identifier("an annotation type or '>'");
            effect::Annotation a;
            a.where = at(type);
            a.type = type.text;
            a.name = expect_identifier("an annotation name").text;
            expect("=", "after annotation " + a.name);
            const auto value = parse_value({";", ">"});
            accept(";");
            if (!value) continue;  // an expression: ignored as FX Composer shows only constants
            a.value = *value;
            annotations.push_back(std::move(a));
            if (annotations.size() > 256) fail(open, "more than 256 annotations");
        }
        return annotations;
    }

    // --- globals ------------------------------------------------------------------------------
    static bool is_texture_keyword(const std::string& word) {
        const std::string w = to_lower(word);
        return w == "texture" || w == "texture1d" || w == "texture2d" || w == "texture3d" || w == "texturecube" || w == "texturerect";
    }

    static bool is_dx10_state_object(const std::string& word) {
        const std::string w = to_lower(word);
        return w == "rasterizerstate" || w == "depthstencilstate" || w == "blendstate" || w == "samplerstate" || w == "samplercomparisonstate";
    }

    // DirectX 10 `RasterizerState NAME { ... };` and kin: only DX10 techniques use them. A
    // SamplerState keeps its declaration (DX10 functions may name it) without the state block.
    void parse_dx10_state_object() {
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

    void parse_string_global() {
        const Token first = next();
        const Token name = expect_identifier("a name after 'string'");
        if (accept(":")) next();
        parse_annotations();
        if (accept("=")) parse_value({";"});
        expect(";", "after string " + name.text);
        blank(first.begin, last_end_);
    }

    void parse_texture() {
        const Token keyword = next();
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
        blank(keyword.begin, last_end_);
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
    void parse_declaration() {
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
        if (is(peek(), "<")) {  // vector<float, 4>, matrix<float, 4, 4>
            const Token open = next();
            while (!accept(">"))
                if (next().kind == TokenKind::End) fail(open, "'<' is never closed");
        }
        const Token name = next();
        if (name.kind != TokenKind::Identifier) fail(name, "expected a name after '" + excerpt(type.text) + "', found '" + excerpt(name.text) + "'");
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
    bool parse_variable(const Token& type, const Token& name, bool is_static) {
        LegacyGlobal global;
        global.type = type.text;
        global.name = name.text;
        global.where = at(name);
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
                global.default_value = parse_value({";", ","});
                blank(begin, last_end_);
            }
        }
        for (const auto& a : global.annotations)
            if (to_lower(a.name) == "texture" && a.value.is_string) global.texture = a.value.text;
        // DX9's untyped sampler: typed at the end, from its texture or from how the code samples it.
        if (sampler && global.type == "sampler" && !is_static) untyped_.push_back({type.begin, type.end, source_.globals.size()});
        if (is_matrix_type(global.type)) matrices_.insert(global.name);
        if (is_static) return true;
        if (to_lower(global.semantic) == "standardsglobal") {  // `float Script : STANDARDSGLOBAL` is no parameter
            source_.effect_annotations = global.annotations;
            return false;
        }
        source_.globals.push_back(std::move(global));
        return true;
    }

    effect::TextureResource* find_texture(const std::string& name) {
        for (auto& t : source_.textures)
            if (t.name == name) return &t;
        return nullptr;
    }

    // Whether the code calls FUNCTION(NAME ...) (blanks allowed around the parenthesis).
    bool sampled_with(const std::string& function, const std::string& name) const {
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

    void type_untyped_samplers() {
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

    void parse_sampler_state(LegacyGlobal& global) {
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
    void parse_function(const Token& type, const Token& name) {
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
    void count_mul_uses(const Token& open) {
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
            if (first_matrix && !second_matrix) ++source_.column_vector_uses;
            if (second_matrix && !first_matrix) ++source_.row_vector_uses;
        }
    }

    // --- techniques ---------------------------------------------------------------------------
    void parse_technique() {
        const Token keyword = next();
        LegacyTechnique technique;
        const Token name = expect_identifier("a technique name");
        technique.name = name.text;
        technique.where = at(name);
        technique.annotations = parse_annotations();
        const Token open = expect("{", "to open technique " + technique.name);
        while (!accept("}")) {
            const Token pass = next();
            if (pass.kind == TokenKind::End) fail(open, "unterminated technique " + technique.name + ": '{' is never closed");
            if (!is(pass, "pass")) fail(pass, "expected 'pass' or '}' in technique " + technique.name + ", found '" + excerpt(pass.text) + "'");
            technique.passes.push_back(parse_pass(technique));
        }
        accept(";");
        blank(keyword.begin, last_end_);
        if (technique.passes.empty()) fail(name, "technique " + technique.name + " has no pass");
        source_.techniques.push_back(std::move(technique));
    }

    LegacyPass parse_pass(const LegacyTechnique& technique) {
        LegacyPass pass;
        const Token first = peek();
        pass.where = at(first);
        pass.name = first.kind == TokenKind::Identifier ? next().text : "p" + std::to_string(technique.passes.size());
        pass.annotations = parse_annotations();
        const Token open = expect("{", "to open pass " + pass.name);
        while (!accept("}")) {
            const Token state = next();
            if (state.kind == TokenKind::End) fail(open, "unterminated pass " + pass.name + ": '{' is never closed");
            if (state.kind != TokenKind::Identifier) fail(state, "expected a state name in pass " + pass.name + ", found '" + excerpt(state.text) + "'");
            if (is(peek(), "[")) skip_balanced(next());  // Sampler[0] = ...
            expect("=", "after " + state.text);
            const std::string key = to_lower(state.text);
            const bool vertex = key == "vertexshader" || key == "vertexprogram";
            const bool fragment = key == "pixelshader" || key == "fragmentprogram" || key == "fragmentshader";
            const bool geometry = key == "geometryshader" || key == "geometryprogram";
            if (vertex || fragment || geometry) {
                pass.programs.push_back(parse_compile(state, vertex ? effect::ShaderStage::Vertex
                                                             : fragment ? effect::ShaderStage::Fragment
                                                                        : effect::ShaderStage::Geometry));
                continue;
            }
            std::vector<Token> value;
            while (!is(peek(), ";")) {
                const Token t = next();
                if (t.kind == TokenKind::End || is(t, "}")) fail(state, "the value of " + state.text + " never ends (missing ';')");
                value.push_back(t);
            }
            next();  // ;
            set_legacy_render_state(pass.states, state.text, value, at(state), source_.warnings, warned_);
        }
        return pass;
    }

    CompileStatement parse_compile(const Token& state, effect::ShaderStage stage) {
        CompileStatement statement;
        statement.stage = stage;
        statement.where = at(state);
        const Token keyword = next();
        if (keyword.text == "NULL" || keyword.text == "null") fail(keyword, state.text + " = NULL is not supported");
        if (keyword.text != "compile") fail(keyword, state.text + " needs 'compile PROFILE function(...)', found '" + excerpt(keyword.text) + "'");
        statement.profile = expect_identifier("a profile after 'compile'").text;
        statement.function = expect_identifier("a function after the profile").text;
        const Token open = expect("(", "after " + statement.function);
        std::string argument;
        for (int depth = 1;;) {
            const Token t = next();
            if (t.kind == TokenKind::End) fail(open, "the arguments of " + statement.function + " are never closed");
            if (is(t, "(") || is(t, "[") || is(t, "{")) ++depth;
            if (is(t, ")") || is(t, "]") || is(t, "}")) --depth;
            if (depth == 0 || (depth == 1 && is(t, ","))) {
                if (!argument.empty()) statement.arguments.push_back(argument);
                argument.clear();
                if (depth == 0) break;
                continue;
            }
            argument += (argument.empty() ? "" : " ") + (t.kind == TokenKind::String ? "\"" + t.text + "\"" : t.text);
        }
        expect(";", "after the compile statement");
        return statement;
    }

    struct Edit {
        size_t begin, end;
        std::string with;
    };
    const effect::Effect& effect_;
    const std::string& text_;
    effect::Lexer lexer_;
    size_t last_end_ = 0;
    std::vector<Edit> edits_;
    struct Untyped {
        size_t begin, end;  // the `sampler` token
        size_t global;      // index in source_.globals
    };
    std::vector<Untyped> untyped_;
    std::set<std::string> matrices_;  // matrix-typed globals and parameters (for mul() counting)
    std::set<std::string> warned_;    // state names already warned about
    LegacySource source_;
};

}  // namespace

LegacySource parse_legacy_source(const effect::Effect& effect) { return LegacyParser(effect).parse(); }

}  // namespace fxview::legacy
