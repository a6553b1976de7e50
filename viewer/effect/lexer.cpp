#include "effect/lexer.hpp"

#include <cctype>

namespace fxview::effect {

void Lexer::skip_space_and_comments() {
    while (position_ < text_.size()) {
        const char c = text_[position_];
        if (std::isspace(static_cast<unsigned char>(c))) {
            ++position_;
        } else if (text_.substr(position_, 2) == "//") {
            const size_t end = text_.find('\n', position_);
            position_ = end == std::string_view::npos ? text_.size() : end;
        } else if (text_.substr(position_, 2) == "/*") {
            const size_t end = text_.find("*/", position_ + 2);
            if (end == std::string_view::npos) {
                unterminated = position_;
                position_ = text_.size();
            } else {
                position_ = end + 2;
            }
        } else {
            return;
        }
    }
}

Token Lexer::peek() {
    const size_t saved = position_;
    Token token = next();
    position_ = saved;
    return token;
}

Token Lexer::next() {
    skip_space_and_comments();
    Token token;
    token.begin = position_;
    if (position_ >= text_.size()) {
        token.end = position_;
        return token;
    }
    const char c = text_[position_];
    const auto is_word = [](char ch) { return std::isalnum(static_cast<unsigned char>(ch)) || ch == '_'; };
    if (c == '#') {
        // A preprocessor line (#define, #if, ...): the whole line, continuation lines included.
        size_t end = position_;
        while (end < text_.size() && text_[end] != '\n') {
            if (text_[end] == '\\' && end + 1 < text_.size() && text_[end + 1] == '\n') ++end;
            ++end;
        }
        token.kind = TokenKind::Preprocessor;
        position_ = end;
    } else if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
        while (position_ < text_.size() && is_word(text_[position_])) ++position_;
        token.kind = TokenKind::Identifier;
    } else if (std::isdigit(static_cast<unsigned char>(c)) ||
               (c == '.' && position_ + 1 < text_.size() && std::isdigit(static_cast<unsigned char>(text_[position_ + 1])))) {
        while (position_ < text_.size() &&
               (is_word(text_[position_]) || text_[position_] == '.' ||
                ((text_[position_] == '-' || text_[position_] == '+') &&
                 (text_[position_ - 1] == 'e' || text_[position_ - 1] == 'E'))))
            ++position_;
        token.kind = TokenKind::Number;
    } else if (c == '"') {
        const size_t end = text_.find_first_of("\"\n", position_ + 1);
        if (end == std::string_view::npos || text_[end] == '\n') {
            unterminated = position_;
            position_ = end == std::string_view::npos ? text_.size() : end;
            token.kind = TokenKind::String;
            token.text = std::string(text_.substr(token.begin + 1, position_ - token.begin - 1));
            token.end = position_;
            return token;
        }
        token.kind = TokenKind::String;
        token.text = std::string(text_.substr(position_ + 1, end - position_ - 1));
        position_ = end + 1;
        token.end = position_;
        return token;
    } else {
        ++position_;
        token.kind = TokenKind::Punct;
    }
    token.end = position_;
    token.text = std::string(text_.substr(token.begin, token.end - token.begin));
    return token;
}

}  // namespace fxview::effect
