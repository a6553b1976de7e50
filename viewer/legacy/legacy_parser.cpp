#include <algorithm>
#include <charconv>
#include <cmath>
#include <set>

#include "core/text.hpp"
#include "effect/texture_annotations.hpp"
#include "legacy/legacy_parser.hpp"

#include "legacy/constant_value.hpp"
#include "legacy/legacy_states.hpp"

namespace fxview::legacy {

namespace {

// The input primitive that opens a Cg geometry program's entry ("TRIANGLE void main(AttribArray<...> ...)").
bool is_geometry_primitive(const std::string& word) {
    return word == "POINT" || word == "LINE" || word == "LINE_ADJ" || word == "TRIANGLE" || word == "TRIANGLE_ADJ";
}

}  // namespace

LegacySource LegacyParser::parse() {
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
        } else if (token.kind == TokenKind::Identifier && is_geometry_primitive(token.text)) {
            // A Cg geometry program: out of the code (glslang cannot read it); a pass that compiles
            // it fails its technique, and the effect's other techniques open.
            skip_declaration();
            blank(token.begin, last_end_);
            source_.warnings.push_back(at(token).str() + ": warning: Cg geometry program (" + token.text +
                                       " ..., profiles gp4gp/gp5gp) skipped: fxview has no geometry stage for Cg");
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

// After an opening token has been read: to the matching close of ( [ { (the close is consumed).
void LegacyParser::skip_balanced(const Token& open) {
    int depth = 1;
    while (depth > 0) {
        const Token t = next();
        if (t.kind == TokenKind::End) fail(open, "'" + open.text + "' is never closed");
        if (t.kind != TokenKind::Punct) continue;
        if (t.text == "(" || t.text == "[" || t.text == "{") ++depth;
        if (t.text == ")" || t.text == "]" || t.text == "}") --depth;
    }
}

void LegacyParser::skip_to_block_end(const Token& first) {
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
void LegacyParser::skip_declaration() {
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

std::string LegacyParser::newlines(size_t begin, size_t end) const {
    return std::string(static_cast<size_t>(std::count(text_.begin() + static_cast<long>(begin), text_.begin() + static_cast<long>(end), '\n')), '\n');
}

std::string LegacyParser::apply_edits() {
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
std::optional<double> LegacyParser::number_of(const Token& token, bool negative) const {
    const std::optional<double> value = legacy_number(token.text);
    return value && negative ? std::optional<double>(-*value) : value;
}

// A constant: 1.5, -2, true, "text" "more", {1, 2}, float3(1, 2, 3), 1.0 / 2.2 (constant_value.hpp);
// nullopt (tokens consumed up to `stop`) for an expression that is no constant.
std::optional<effect::Value> LegacyParser::parse_value(const std::set<std::string>& stops) {
    effect::Value value;
    Token t = peek();
    if (t.kind == TokenKind::String) {
        value.is_string = true;
        while (peek().kind == TokenKind::String) value.text += next().text;
        return value;
    }
    std::vector<Token> tokens;
    for (int depth = 0;;) {
        t = peek();
        if (t.kind == TokenKind::End) fail(t, "value never ends");
        if (depth == 0 && t.kind == TokenKind::Punct && stops.count(t.text)) break;
        next();
        if (is(t, "{") || is(t, "(")) ++depth;
        if (is(t, "}") || is(t, ")")) --depth;
        tokens.push_back(t);
    }
    const std::optional<std::vector<double>> numbers = constant_numbers(tokens);
    if (!numbers || numbers->empty()) return std::nullopt;
    value.numbers = *numbers;
    return value;
}

std::vector<effect::Annotation> LegacyParser::parse_annotations() {
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

// --- techniques ---------------------------------------------------------------------------
void LegacyParser::parse_technique() {
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
        if (++passes_ > kMaxPasses) fail(pass, "more than " + std::to_string(kMaxPasses) + " passes in one effect");
        technique.passes.push_back(parse_pass(technique));
    }
    accept(";");
    blank(keyword.begin, last_end_);
    if (technique.passes.empty()) fail(name, "technique " + technique.name + " has no pass");
    if (source_.techniques.size() >= kMaxTechniques) fail(name, "more than " + std::to_string(kMaxTechniques) + " techniques in one effect");
    source_.techniques.push_back(std::move(technique));
}

LegacyPass LegacyParser::parse_pass(const LegacyTechnique& technique) {
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
        if (vertex && (is(peek(), "NULL") || is(peek(), "null"))) {  // the fixed-function vertex stage (legacy_effect.cpp)
            next();
            expect(";", "after " + state.text + " = NULL");
            pass.fixed_function_vertex = true;
            continue;
        }
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

CompileStatement LegacyParser::parse_compile(const Token& state, effect::ShaderStage stage) {
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

LegacySource parse_legacy_source(const effect::Effect& effect) { return LegacyParser(effect).parse(); }

}  // namespace fxview::legacy
