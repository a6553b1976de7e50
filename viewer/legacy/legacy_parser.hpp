// The reader of a legacy effect's effect level (legacy_source.hpp): a walk over the preprocessed
// text's tokens that records globals, textures, samplers, functions and techniques, and blanks what
// the shader compiler must not see. Internal to viewer/legacy: legacy_parser.cpp holds the walk,
// the values and the techniques, legacy_declarations.cpp the globals and functions.
#pragma once
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "effect/lexer.hpp"
#include "legacy/legacy_source.hpp"

namespace fxview::legacy {

using effect::Token;
using effect::TokenKind;

inline bool is_matrix_type(const std::string& type) {
    // float4x4, half3x3, fixed2x2, double4x3, int3x3, matrix
    if (type == "matrix") return true;
    const size_t x = type.size() >= 3 ? type.size() - 2 : std::string::npos;
    return x != std::string::npos && type[x] == 'x' && std::isdigit(static_cast<unsigned char>(type[x - 1])) &&
           std::isdigit(static_cast<unsigned char>(type[x + 1]));
}

inline const std::set<std::string> kQualifiers = {"static", "const", "uniform", "extern", "shared", "volatile", "row_major",
                                           "column_major", "inline", "precise", "groupshared", "nointerpolation", "in",
                                           "out", "inout", "linear", "centroid", "noperspective", "sample"};

class LegacyParser {
public:
    explicit LegacyParser(const effect::Effect& effect) : effect_(effect), text_(effect.sources.text()), lexer_(text_) {}

    LegacySource parse();

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
    void skip_balanced(const Token& open);
    void skip_to_block_end(const Token& first);
    // A declaration kept as code: to its ';' at depth 0, or through its block and an optional ';'.
    void skip_declaration();

    // --- edits of the code: blanked spans keep their newlines ---------------------------------
    void blank(size_t begin, size_t end) { edits_.push_back({begin, end, newlines(begin, end)}); }
    void replace(size_t begin, size_t end, std::string with) { edits_.push_back({begin, end, std::move(with)}); }
    std::string newlines(size_t begin, size_t end) const;
    std::string apply_edits();

    // --- values and annotations ---------------------------------------------------------------
    std::optional<double> number_of(const Token& token, bool negative) const;
    // A constant: 1.5, -2, true, "text" "more", {1, 2}, float3(1, 2, 3); nullopt (tokens consumed
    // up to `stop`) for an expression this reader does not evaluate.
    std::optional<effect::Value> parse_value(const std::set<std::string>& stops);
    std::vector<effect::Annotation> parse_annotations();

    // --- globals ------------------------------------------------------------------------------
    static bool is_texture_keyword(const std::string& word) {
        const std::string w = to_lower(word);
        return w == "texture" || w == "texture1d" || w == "texture2d" || w == "texture3d" || w == "texturecube" || w == "texturerect";
    }

    static bool is_dx10_state_object(const std::string& word);

    // DirectX 10 `RasterizerState NAME { ... };` and kin: only DX10 techniques use them. A
    // SamplerState keeps its declaration (DX10 functions may name it) without the state block.
    void parse_dx10_state_object();

    void parse_string_global();

    void parse_texture();
    void parse_texture_after(const Token& keyword, size_t begin);

    // TYPE NAME [N] [: SEMANTIC] [<annotations>] [= value | = sampler_state { ... }] ; or a function.
    void parse_declaration();

    // Returns false for a declaration that is no shader variable (the SAS STANDARDSGLOBAL).
    bool parse_variable(const Token& type, const Token& name, bool is_static);

    effect::TextureResource* find_texture(const std::string& name);

    // Whether the code calls FUNCTION(NAME ...) (blanks allowed around the parenthesis).
    bool sampled_with(const std::string& function, const std::string& name) const;

    void type_untyped_samplers();

    void parse_sampler_state(LegacyGlobal& global);

    // --- functions ----------------------------------------------------------------------------
    void parse_function(const Token& type, const Token& name);

    // Counts mul(M, x) and mul(x, M) for matrix-typed names M inside a function body (consumed).
    void count_mul_uses(const Token& open);

    // --- techniques ---------------------------------------------------------------------------
    void parse_technique();

    LegacyPass parse_pass(const LegacyTechnique& technique);

    CompileStatement parse_compile(const Token& state, effect::ShaderStage stage);

    // The caps of native effects (parser.cpp): far above any real file, they bound what a hostile one costs.
    static constexpr size_t kMaxGlobals = 4096, kMaxTechniques = 256, kMaxPasses = 256;
    size_t passes_ = 0;
    std::map<std::string, effect::SourceLocation> declared_;  // top-level variables, for redeclarations
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
    std::set<std::string> transposed_;  // those of them bound to a ...Transpose semantic
    std::set<std::string> warned_;    // state names already warned about
    LegacySource source_;
};

}  // namespace fxview::legacy
