// TokenReader (token_reader.hpp).
#include "effect/token_reader.hpp"

#include <charconv>

#include "core/text.hpp"

namespace fxview::effect {

SourceLocation TokenReader::at(const Token& token) const { return sources_.locate(token.begin); }

// excerpt() keeps one hostile token from making a megabyte message.
void TokenReader::fail(const Token& token, const std::string& message) const {
    throw EffectError(at(token), excerpt(message, 400));
}

void TokenReader::check_unterminated() const {
    if (lexer_.unterminated != std::string_view::npos)
        throw EffectError(sources_.locate(lexer_.unterminated), "unterminated comment or string");
}

Token TokenReader::next() {
    Token token = lexer_.next();
    check_unterminated();
    // GLSL allows identifiers of up to 1024 characters; longer words are data, not source.
    if ((token.kind == TokenKind::Identifier || token.kind == TokenKind::Number) && token.text.size() > kMaxWord)
        fail(token, "a word of " + std::to_string(token.text.size()) + " characters (at most " + std::to_string(kMaxWord) + ")");
    return token;
}

Token TokenReader::expect_identifier(const std::string& what) {
    const Token token = next();
    if (token.kind != TokenKind::Identifier)
        fail(token, "expected " + what + ", found " + (token.kind == TokenKind::End ? "end of file" : "'" + token.text + "'"));
    return token;
}

Token TokenReader::expect(char punct, const std::string& context) {
    const Token token = next();
    if (token.kind != TokenKind::Punct || token.text[0] != punct)
        fail(token, std::string("expected '") + punct + "' " + context + ", found " +
                        (token.kind == TokenKind::End ? "end of file" : "'" + token.text + "'"));
    return token;
}

bool TokenReader::accept(char punct) {
    const Token token = lexer_.peek();
    if (token.kind == TokenKind::Punct && token.text[0] == punct) {
        next();
        return true;
    }
    return false;
}

Token TokenReader::skip_block(const Token& open, const std::string& what) {
    int depth = 1;
    for (;;) {
        const Token token = next();
        if (token.kind == TokenKind::End) fail(open, "unterminated " + what + ": '{' is never closed");
        if (token.kind != TokenKind::Punct) continue;
        if (token.text[0] == '{') ++depth;
        if (token.text[0] == '}' && --depth == 0) return token;
    }
}

double TokenReader::parse_number(const Token& token, bool negative) {
    std::string text = token.text;
    while (!text.empty() && (text.back() == 'f' || text.back() == 'F' || text.back() == 'u' || text.back() == 'U'))
        text.pop_back();
    double value = 0.0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size()) fail(token, "malformed number '" + token.text + "'");
    return negative ? -value : value;
}

Value TokenReader::parse_value() {
    Value value;
    Token token = next();
    if (token.kind == TokenKind::String) {
        value.is_string = true;
        value.text = token.text;
        return value;
    }
    const bool list = token.kind == TokenKind::Punct && token.text == "{";
    const bool constructor = token.kind == TokenKind::Identifier && lexer_.peek().text == "(" ;
    if (list || constructor) {
        if (constructor) next();  // '('
        const char close = list ? '}' : ')';
        if (!accept(close))
            do value.numbers.push_back(parse_scalar(next())); while (accept(','));
        expect(close, "to end the value list");
        return value;
    }
    value.numbers.push_back(parse_scalar(token));
    return value;
}

double TokenReader::parse_scalar(Token token) {
    bool negative = false;
    if (token.kind == TokenKind::Punct && (token.text == "-" || token.text == "+")) {
        negative = token.text == "-";
        token = next();
    }
    if (token.kind == TokenKind::Number) return parse_number(token, negative);
    if (token.kind == TokenKind::Identifier && (token.text == "true" || token.text == "false") && !negative)
        return token.text == "true" ? 1.0 : 0.0;
    fail(token, "expected a number, found " + (token.kind == TokenKind::End ? "end of file" : "'" + token.text + "'"));
}

std::vector<Annotation> TokenReader::parse_annotations() {
    std::vector<Annotation> annotations;
    if (!accept('<')) return annotations;
    while (!accept('>')) {
        Annotation annotation;
        const Token type = expect_identifier("an annotation type (string, float, int, bool) or '>'");
        annotation.where = at(type);
        annotation.type = type.text;
        annotation.name = expect_identifier("an annotation name after '" + type.text + "'").text;
        expect('=', "after annotation " + annotation.name);
        annotation.value = parse_value();
        const std::string t = to_lower(annotation.type);
        if ((t == "string") != annotation.value.is_string)
            throw EffectError(annotation.where, "annotation " + annotation.name + " is declared " + annotation.type +
                                                    " but its value is " + (annotation.value.is_string ? "a string" : "not a string"));
        expect(';', "after annotation " + annotation.name);
        annotations.push_back(std::move(annotation));
    }
    return annotations;
}

}  // namespace fxview::effect
