// Tokens of the effect syntax over the expanded source. GLSL inside shader blocks and functions is
// not interpreted: the parser only uses the lexer to find where such text ends (braces, strings and
// comments respected).
#pragma once
#include <string>
#include <string_view>

namespace fxview::effect {

enum class TokenKind { Identifier, Number, String, Punct, Preprocessor, End };

struct Token {
    TokenKind kind = TokenKind::End;
    std::string text;  // strings without quotes; punctuation as one character
    size_t begin = 0, end = 0;
};

class Lexer {
public:
    explicit Lexer(std::string_view text) : text_(text) {}
    Token next();
    Token peek();
    // Error offset of an unterminated comment or string found while scanning, else npos.
    size_t unterminated = std::string_view::npos;

private:
    void skip_space_and_comments();
    std::string_view text_;
    size_t position_ = 0;
};

}  // namespace fxview::effect
