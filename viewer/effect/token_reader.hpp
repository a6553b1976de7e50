// Reading an effect file token by token: expecting and accepting punctuation, numbers, constant
// values and annotation lists, with errors that name file and line. The effect parser's grammar
// (parser.cpp) is built on it.
#pragma once
#include <string>
#include <vector>

#include "effect/effect.hpp"
#include "effect/lexer.hpp"
#include "effect/source_map.hpp"

namespace fxview::effect {

class TokenReader {
public:
    explicit TokenReader(const SourceMap& sources) : sources_(sources), lexer_(sources.text()) {}

protected:
    SourceLocation at(const Token& token) const;
    // Throws EffectError at `token`; messages quote tokens, cut to a few hundred characters.
    [[noreturn]] void fail(const Token& token, const std::string& message) const;
    void check_unterminated() const;

    Token next();  // words longer than GLSL's 1024 characters are refused
    Token expect_identifier(const std::string& what);
    Token expect(char punct, const std::string& context);
    bool accept(char punct);  // reads `punct` if it comes next
    // From an opening brace just read to its matching closing brace; returns the closing token.
    Token skip_block(const Token& open, const std::string& what);

    double parse_number(const Token& token, bool negative);
    // A constant: 1.5, -2, true, "text", {1, 2, 3} or vec3(1, 2, 3).
    Value parse_value();
    double parse_scalar(Token token);
    // `< type name = value; ... >`, or nothing where no '<' follows.
    std::vector<Annotation> parse_annotations();

    const SourceMap& sources_;
    Lexer lexer_;

private:
    static constexpr size_t kMaxWord = 1024;
};

}  // namespace fxview::effect
