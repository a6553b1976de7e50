#include "legacy/buffer_blocks.hpp"

#include <algorithm>
#include <optional>

#include "core/text.hpp"
#include "effect/effect.hpp"
#include "effect/lexer.hpp"

namespace fxview::legacy {
namespace {

using effect::Token;
using effect::TokenKind;

bool is(const Token& t, const char* text) { return t.kind != TokenKind::String && t.text == text; }

struct Member {
    std::string type, name, array, semantic;  // array: "[N]" as written, semantic without ':'
    size_t offset = 0;                        // where its declaration starts in the block's body
};

// The members of a block body ("float4 a; float3x3 b[2], c : SEM;"), or the token where it holds
// anything else.
std::vector<Member> read_members(const std::string& body, std::optional<Token>& unreadable) {
    std::vector<Member> members;
    effect::Lexer lexer(body);
    const auto refuse = [&](const Token& t) {
        unreadable = t;
        return std::vector<Member>{};
    };
    for (;;) {
        Token type = lexer.next();
        if (type.kind == TokenKind::End) break;
        const size_t offset = type.begin;
        while (type.kind == TokenKind::Identifier && (type.text == "row_major" || type.text == "column_major")) type = lexer.next();
        if (type.kind != TokenKind::Identifier || type.text == "struct") return refuse(type);
        for (;;) {
            Member m{type.text, "", "", "", offset};
            const Token name = lexer.next();
            if (name.kind != TokenKind::Identifier) return refuse(name);
            m.name = name.text;
            if (is(lexer.peek(), "[")) {
                lexer.next();
                const Token size = lexer.next();
                if (size.kind != TokenKind::Number) return refuse(size);
                if (const Token shut = lexer.next(); !is(shut, "]")) return refuse(shut);
                m.array = "[" + size.text + "]";
            }
            if (is(lexer.peek(), ":")) {
                lexer.next();
                const Token semantic = lexer.next();
                if (semantic.kind != TokenKind::Identifier) return refuse(semantic);
                m.semantic = semantic.text;
            }
            members.push_back(m);
            const Token separator = lexer.next();
            if (is(separator, ";")) break;
            if (!is(separator, ",")) return refuse(separator);
        }
    }
    if (members.empty()) return refuse(Token{TokenKind::End, "}", body.size(), body.size()});
    return members;
}

size_t newlines(const std::string& text, size_t begin, size_t end) {
    return static_cast<size_t>(std::count(text.begin() + static_cast<std::ptrdiff_t>(begin), text.begin() + static_cast<std::ptrdiff_t>(end), '\n'));
}

}  // namespace

std::string rewrite_buffer_blocks(const std::string& text, const effect::SourceMap& sources, std::vector<std::string>& warnings) {
    std::string out;
    size_t copied = 0;
    effect::Lexer lexer(text);
    Token previous;
    for (Token t = lexer.next(); t.kind != TokenKind::End; previous = t, t = lexer.next()) {
        if (!is(t, "struct")) continue;
        const size_t begin = is(previous, "uniform") ? previous.begin : t.begin;
        Token open = lexer.next();
        if (open.kind == TokenKind::Identifier) open = lexer.next();  // the struct's own name
        if (!is(open, "{")) continue;
        // To the matching close; a nested brace makes it no block this reads, if it is one at all.
        Token close = lexer.next();
        bool nested = false;
        for (int depth = 1; close.kind != TokenKind::End; close = lexer.next()) {
            if (is(close, "{")) ++depth, nested = true;
            if (is(close, "}") && --depth == 0) break;
        }
        if (!is(close, "}")) continue;  // unterminated: the parser says so
        const Token variable = lexer.next();
        if (variable.kind != TokenKind::Identifier || !is(lexer.peek(), ":")) continue;
        lexer.next();
        if (!is(lexer.peek(), "BUFFER")) continue;
        lexer.next();
        const Token bracket = lexer.next(), index = lexer.next(), shut = lexer.next(), end = lexer.next();
        const std::string what = "Cg 3 buffer " + variable.text + ": ";
        if (!is(bracket, "[") || index.kind != TokenKind::Number || !is(shut, "]") || !is(end, ";"))
            throw effect::EffectError(sources.locate(variable.begin), what + "expected BUFFER[n]; after its name");
        const std::string body = text.substr(open.end, close.begin - open.end);
        std::optional<Token> unreadable;
        const std::vector<Member> members = nested ? std::vector<Member>{} : read_members(body, unreadable);
        if (nested)
            throw effect::EffectError(sources.locate(open.end), what + "nested struct definitions are not supported; declare the struct before the block");
        if (members.empty())
            throw effect::EffectError(sources.locate(open.end + unreadable->begin),
                                      what + (unreadable->kind == TokenKind::End ? "it has no members"
                                                                                  : "each member must read TYPE name[N] [: SEMANTIC]; found '" + excerpt(unreadable->text) + "'"));
        // Line for line: each member's global on the member's own line (a compiler's message about a
        // member lands there first), the struct and its instance on the block's last line.
        const std::string type = "__fxbuffer_" + variable.text;
        std::vector<std::string> lines(newlines(text, begin, end.end) + 1);
        std::string definition = "struct " + type + " {";
        for (const Member& m : members) definition += " " + m.type + " " + m.name + m.array + ";";
        std::string initialiser, unfilled;
        for (const Member& m : members) {
            const std::string global = variable.text + "_" + m.name;
            lines[newlines(text, begin, open.end + m.offset)] += " " + m.type + " " + global + m.array + (m.semantic.empty() ? "" : " : " + m.semantic) + ";";
            initialiser += (initialiser.empty() ? "" : ", ") + global;
            if (m.semantic.empty()) unfilled += (unfilled.empty() ? "" : ", ") + global;
        }
        lines.back() += " " + definition + " }; static " + type + " " + variable.text + " = { " + initialiser + " };";
        std::string rewritten;
        for (size_t i = 0; i < lines.size(); ++i) rewritten += (i > 0 ? "\n" : "") + lines[i];
        out += text.substr(copied, begin - copied) + rewritten;
        copied = end.end;
        warnings.push_back(sources.locate(begin).str() + ": warning: Cg 3 buffer " + variable.text + " (BUFFER[" + index.text +
                           "]) is read as parameters " + variable.text + "_MEMBER" +
                           (unfilled.empty() ? "" : "; " + unfilled + " start at 0 (an application filled them)"));
        previous = end;
    }
    return copied == 0 ? text : out + text.substr(copied);
}

}  // namespace fxview::legacy
