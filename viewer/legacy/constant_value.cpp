#include "legacy/constant_value.hpp"

#include <charconv>
#include <cmath>

namespace fxview::legacy {

std::optional<double> legacy_number(const std::string& literal) {
    std::string text = literal;
    while (!text.empty() && std::string("fFhHuUlL").find(text.back()) != std::string::npos) text.pop_back();
    double value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size()) return std::nullopt;
    return value;
}

namespace {

using effect::Token;

// float, float3, half4x4, int2, ...: a constructor's type (sqrt(2) is a call, no constant).
bool is_vector_type(const std::string& name) {
    for (const char* base : {"float", "half", "double", "int", "uint", "bool", "fixed", "dword"}) {
        const std::string b = base;
        if (name.compare(0, b.size(), b) != 0) continue;
        const std::string rest = name.substr(b.size());
        const auto digit = [](char c) { return c >= '1' && c <= '4'; };
        if (rest.empty() || (rest.size() == 1 && digit(rest[0])) || (rest.size() == 3 && digit(rest[0]) && rest[1] == 'x' && digit(rest[2]))) return true;
    }
    return false;
}
using effect::TokenKind;

// Recursive descent over the tokens: list := item (',' item)*; item := '{' list '}' |
// TYPE '(' list ')' | sum; sum := product (('+'|'-') product)*; product := unary (('*'|'/') unary)*;
// unary := ('+'|'-') unary | NUMBER | true | false | '(' sum ')'.
class Folder {
public:
    explicit Folder(const std::vector<Token>& tokens) : tokens_(tokens) {}

    std::optional<std::vector<double>> all() {
        std::vector<double> numbers;
        if (!list(numbers) || at_ < tokens_.size()) return std::nullopt;
        return numbers;
    }

private:
    bool is(const char* punct) const { return at_ < tokens_.size() && tokens_[at_].kind == TokenKind::Punct && tokens_[at_].text == punct; }
    bool accept(const char* punct) {
        if (!is(punct)) return false;
        ++at_;
        return true;
    }

    bool list(std::vector<double>& out) {
        if (!item(out)) return false;
        while (accept(",")) {
            if (at_ >= tokens_.size() || is("}") || is(")")) break;  // a trailing comma
            if (!item(out)) return false;
        }
        return true;
    }

    bool item(std::vector<double>& out) {
        if (accept("{")) return list(out) && accept("}");
        if (at_ + 1 < tokens_.size() && tokens_[at_].kind == TokenKind::Identifier && is_vector_type(tokens_[at_].text) &&
            tokens_[at_ + 1].kind == TokenKind::Punct && tokens_[at_ + 1].text == "(") {
            at_ += 2;  // a constructor: float3(1, 2, 3)
            return list(out) && accept(")");
        }
        const std::optional<double> value = sum();
        if (!value) return false;
        out.push_back(*value);
        return true;
    }

    std::optional<double> sum() {
        std::optional<double> value = product();
        while (value && (is("+") || is("-"))) {
            const bool plus = tokens_[at_++].text == "+";
            const std::optional<double> right = product();
            if (!right) return std::nullopt;
            value = plus ? *value + *right : *value - *right;
        }
        return value;
    }

    std::optional<double> product() {
        std::optional<double> value = unary();
        while (value && (is("*") || is("/"))) {
            const bool times = tokens_[at_++].text == "*";
            const std::optional<double> right = unary();
            if (!right) return std::nullopt;
            value = times ? *value * *right : *value / *right;
        }
        if (value && !std::isfinite(*value)) return std::nullopt;  // 1 / 0
        return value;
    }

    std::optional<double> unary() {
        if (accept("-")) {
            const std::optional<double> value = unary();
            return value ? std::optional<double>(-*value) : std::nullopt;
        }
        if (accept("+")) return unary();
        if (accept("(")) {
            const std::optional<double> value = sum();
            return value && accept(")") ? value : std::nullopt;
        }
        if (at_ >= tokens_.size()) return std::nullopt;
        const Token& t = tokens_[at_++];
        if (t.kind == TokenKind::Number) return legacy_number(t.text);
        if (t.kind == TokenKind::Identifier && (t.text == "true" || t.text == "false")) return t.text == "true" ? 1.0 : 0.0;
        return std::nullopt;
    }

    const std::vector<Token>& tokens_;
    size_t at_ = 0;
};

}  // namespace

std::optional<std::vector<double>> constant_numbers(const std::vector<effect::Token>& tokens) {
    if (tokens.empty()) return std::nullopt;
    return Folder(tokens).all();
}

}  // namespace fxview::legacy
