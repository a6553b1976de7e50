#include "legacy/glslang_process.hpp"

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>

#include <algorithm>
#include <cctype>
#include <set>
#include <cstring>
#include <mutex>
#include <sstream>

#include "core/text.hpp"

namespace fxview::legacy {

void ensure_glslang_process() {
    static std::once_flag once;
    std::call_once(once, [] { glslang::InitializeProcess(); });
}

const char* cg_shims() {
    static const std::string shims = [] {
        std::string text =
            "#define fixed float\n#define fixed1 float\n#define fixed2 float2\n#define fixed3 float3\n#define fixed4 float4\n"
            "#define fixed2x2 float2x2\n#define fixed3x3 float3x3\n#define fixed4x4 float4x4\n#define fixed3x4 float3x4\n"
            "#define fixed4x3 float4x3\n#define samplerRECT sampler2D\n#define texRECT tex2D\n#define texRECTproj tex2Dproj\n"
            "#define texRECTlod tex2Dlod\n#define FXVIEW 1\n"
            // Cg's `varying` (per-vertex data, as every in/out of a program is in HLSL) has no HLSL keyword.
            "#define varying\n"
            // glslang 12 makes lit()'s specular term n.h * m instead of pow(n.h, m): HLSL's definition here.
            "#define lit(nl, nh, m) float4(1.0, max((nl), 0.0), ((nl) < 0.0 || (nh) < 0.0) ? 0.0 : pow(max((nh), 0.0), (m)), 1.0)\n";
        // Cg's typed lookups: h4tex2D(s, uv) is tex2D(s, uv) as half4, f3texCUBE(...) its .xyz, ...
        const char* swizzles[] = {"", ".x", ".xy", ".xyz", ""};
        for (const char* function : {"tex1D", "tex2D", "tex3D", "texCUBE", "texRECT", "tex1Dproj", "tex2Dproj", "tex3Dproj", "texCUBEproj", "texRECTproj"})
            for (const char* prefix : {"h", "f", "x"})
                for (int n = 1; n <= 4; ++n)
                    text += "#define " + std::string(prefix) + std::to_string(n) + function + "(s, c) " +
                            (std::string(function).find("RECT") != std::string::npos ? std::string(function).replace(3, 4, "2D") : std::string(function)) +
                            "(s, c)" + swizzles[n] + "\n";
        return text;
    }();
    return shims.c_str();
}

namespace {

// Cg's OpenGL state bindings (glstate.matrix.mvp, ...) as SAS-semantic globals: each path becomes a
// name, declared at the start of the first line that is no directive (lines stay where they are).
void replace_glstate(std::string& text) {
    static const std::pair<const char*, const char*> kBindings[] = {
        {"glstate.matrix.invtrans.modelview[0]", "float4x4 fxview_glstate_modelview_it : WorldViewInverseTranspose;"},
        {"glstate.matrix.inverse.modelview[0]", "float4x4 fxview_glstate_modelview_inverse : WorldViewInverse;"},
        {"glstate.matrix.transpose.modelview[0]", "float4x4 fxview_glstate_modelview_transpose : WorldViewTranspose;"},
        {"glstate.matrix.modelview[0]", "float4x4 fxview_glstate_modelview : WorldView;"},
        {"glstate.matrix.inverse.projection", "float4x4 fxview_glstate_projection_inverse : ProjectionInverse;"},
        {"glstate.matrix.projection", "float4x4 fxview_glstate_projection : Projection;"},
        {"glstate.matrix.inverse.mvp", "float4x4 fxview_glstate_mvp_inverse : WorldViewProjectionInverse;"},
        {"glstate.matrix.mvp", "float4x4 fxview_glstate_mvp : WorldViewProjection;"},
        {"glstate.light[0].position", "float4 fxview_glstate_light0_position : ViewLightPosition;"},
    };
    // glslang's preprocessor writes member access with blanks ("glstate . matrix . mvp"): paths
    // are matched with blanks skipped.
    std::string declarations;
    std::set<std::string> declared;
    for (size_t at = text.find("glstate"); at != std::string::npos; at = text.find("glstate", at + 1)) {
        if (at > 0 && (std::isalnum(static_cast<unsigned char>(text[at - 1])) || text[at - 1] == '_')) continue;
        for (const auto& [path, declaration] : kBindings) {
            size_t i = at, k = 0;
            const size_t length = std::strlen(path);
            while (k < length && i < text.size()) {
                if (text[i] == ' ' || text[i] == '\t') { ++i; continue; }
                if (text[i] != path[k]) break;
                ++i;
                ++k;
            }
            if (k != length) continue;
            const std::string decl = declaration;
            const size_t space = decl.find(' ');
            const std::string name = decl.substr(space + 1, decl.find(' ', space + 1) - space - 1);
            text.replace(at, i - at, name);
            if (declared.insert(name).second) declarations += decl + " ";
            break;
        }
    }
    if (declarations.empty()) return;
    size_t line = 0;
    for (;;) {
        const size_t first = text.find_first_not_of(" \t", line);
        const size_t end = text.find('\n', line);
        if (first == std::string::npos || text[first] != '#' || end == std::string::npos) break;
        line = end + 1;
    }
    text.insert(line, declarations);
}

}  // namespace

std::string preprocess_legacy(const effect::Effect& effect) {
    ensure_glslang_process();
    const std::string& source = effect.sources.text();
    glslang::TShader shader(EShLangFragment);
    const char* text = source.c_str();
    const int length = static_cast<int>(source.size());
    shader.setStringsWithLengths(&text, &length, 1);
    shader.setPreamble(cg_shims());
    shader.setEnvInput(glslang::EShSourceHlsl, EShLangFragment, glslang::EShClientVulkan, 100);
    shader.setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_0);
    shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_0);
    std::string output;
    glslang::TShader::ForbidIncluder includer;  // includes are expanded by SourceMap, under the file policy
    const auto messages = static_cast<EShMessages>(EShMsgReadHlsl | EShMsgHlslDX9Compatible);
    if (!shader.preprocess(GetDefaultResources(), 100, ENoProfile, false, false, messages, &output, includer)) {
        std::istringstream log(shader.getInfoLog());
        for (std::string line; std::getline(log, line);) {
            if (line.rfind("ERROR: ", 0) != 0) continue;
            const std::string rest = line.substr(7);
            const size_t colon = rest.find(':'), second = colon == std::string::npos ? colon : rest.find(':', colon + 1);
            int number = 1;
            if (second != std::string::npos) {
                try { number = std::max(1, std::stoi(rest.substr(colon + 1, second - colon - 1))); } catch (const std::exception&) {}
            }
            // The line's offset in the text: SourceMap locates offsets.
            size_t offset = 0;
            for (int l = 1; l < number && offset != std::string::npos; ++l) offset = source.find('\n', offset) + 1;
            if (offset == std::string::npos || offset == 0) offset = number <= 1 ? 0 : source.size();
            throw effect::EffectError(effect.sources.locate(offset), "preprocessor: " + excerpt(second == std::string::npos ? rest : rest.substr(second + 2), 300));
        }
        throw effect::EffectError({effect.path, 1}, "preprocessor failed");
    }
    // Keep the line count: the effect level and the compiler's messages are located by line.
    const auto count = [](const std::string& s) { return std::count(s.begin(), s.end(), '\n'); };
    while (count(output) < count(source)) output += '\n';
    replace_glstate(output);
    return output;
}

}  // namespace fxview::legacy
