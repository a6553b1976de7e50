#include "legacy/buffer_blocks.hpp"

#include <algorithm>

#include "effect/lexer.hpp"

namespace fxview::legacy {
namespace {

using effect::Token;
using effect::TokenKind;

bool is(const Token& t, const char* text) { return t.kind != TokenKind::String && t.text == text; }

struct Member {
    std::string type, name, array, semantic;  // array: "[N]" as written, semantic without ':'
};

// The members of a block body ("float4 a; float3x3 b[2], c : SEM;"); empty where it holds anything else.
std::vector<Member> read_members(const std::string& body) {
    std::vector<Member> members;
    effect::Lexer lexer(body);
    for (;;) {
        Token type = lexer.next();
        if (type.kind == TokenKind::End) break;
        while (type.kind == TokenKind::Identifier && (type.text == "row_major" || type.text == "column_major")) type = lexer.next();
        if (type.kind != TokenKind::Identifier) return {};
        for (;;) {
            Member m{type.text, "", "", ""};
            const Token name = lexer.next();
            if (name.kind != TokenKind::Identifier) return {};
            m.name = name.text;
            if (is(lexer.peek(), "[")) {
                lexer.next();
                const Token size = lexer.next();
                if (size.kind != TokenKind::Number || !is(lexer.next(), "]")) return {};
                m.array = "[" + size.text + "]";
            }
            if (is(lexer.peek(), ":")) {
                lexer.next();
                const Token semantic = lexer.next();
                if (semantic.kind != TokenKind::Identifier) return {};
                m.semantic = semantic.text;
            }
            members.push_back(m);
            const Token separator = lexer.next();
            if (is(separator, ";")) break;
            if (!is(separator, ",")) return {};
        }
    }
    return members;
}

}  // namespace

std::string rewrite_buffer_blocks(const std::string& text, const effect::SourceMap& sources, std::vector<std::string>& warnings) {
    std::string out;
    size_t copied = 0;
    effect::Lexer lexer(text);
    Token previous;
    for (Token t = lexer.next(); t.kind != TokenKind::End; previous = t, t = lexer.next()) {
        if (!is(t, "struct")) continue;
        const size_t begin = is(previous, "uniform") && previous.end <= t.begin ? previous.begin : t.begin;
        Token open = lexer.next();
        if (open.kind == TokenKind::Identifier) open = lexer.next();  // the struct's own name
        if (!is(open, "{")) continue;
        Token close = lexer.next();
        while (close.kind != TokenKind::End && !is(close, "}") && !is(close, "{")) close = lexer.next();
        if (!is(close, "}")) continue;  // nested braces: no buffer block this reads
        const Token variable = lexer.next();
        if (variable.kind != TokenKind::Identifier || !is(lexer.peek(), ":")) continue;
        lexer.next();
        if (!is(lexer.peek(), "BUFFER")) continue;
        lexer.next();
        const Token bracket = lexer.next(), index = lexer.next(), shut = lexer.next(), end = lexer.next();
        if (!is(bracket, "[") || index.kind != TokenKind::Number || !is(shut, "]") || !is(end, ";")) continue;
        const std::string body = text.substr(open.end, close.begin - open.end);
        const std::vector<Member> members = read_members(body);
        if (members.empty()) continue;
        const std::string type = "__fxbuffer_" + variable.text;
        // On one line (the block's newlines follow the rewrite), from the members as read.
        std::string rewritten = "struct " + type + " {";
        for (const Member& m : members) rewritten += " " + m.type + " " + m.name + m.array + ";";
        rewritten += " }; ";
        std::string initialiser, names;
        for (const Member& m : members) {
            const std::string global = variable.text + "_" + m.name;
            rewritten += m.type + " " + global + m.array + (m.semantic.empty() ? "" : " : " + m.semantic) + "; ";
            initialiser += (initialiser.empty() ? "" : ", ") + global;
            names += (names.empty() ? "" : ", ") + global;
        }
        rewritten += "static " + type + " " + variable.text + " = { " + initialiser + " };";
        // Line for line: the newlines of the block follow it.
        rewritten += std::string(static_cast<size_t>(std::count(text.begin() + static_cast<std::ptrdiff_t>(begin), text.begin() + static_cast<std::ptrdiff_t>(end.end), '\n')), '\n');
        out += text.substr(copied, begin - copied) + rewritten;
        copied = end.end;
        warnings.push_back(sources.locate(begin).str() + ": warning: Cg 3 buffer " + variable.text + " (BUFFER[" + index.text +
                           "]) is read as the parameters " + names + " (an application filled it; here they start at 0)");
        previous = end;
    }
    return copied == 0 ? text : out + text.substr(copied);
}

}  // namespace fxview::legacy
