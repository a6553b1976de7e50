#include "legacy/glslang_process.hpp"

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>

#include <algorithm>
#include <mutex>
#include <sstream>

#include "core/text.hpp"

namespace fxview::legacy {

void ensure_glslang_process() {
    static std::once_flag once;
    std::call_once(once, [] { glslang::InitializeProcess(); });
}

const char* cg_shims() {
    return "#define fixed float\n#define fixed1 float\n#define fixed2 float2\n#define fixed3 float3\n#define fixed4 float4\n"
           "#define fixed2x2 float2x2\n#define fixed3x3 float3x3\n#define fixed4x4 float4x4\n#define fixed3x4 float3x4\n"
           "#define fixed4x3 float4x3\n#define samplerRECT sampler2D\n#define texRECT tex2D\n#define texRECTproj tex2Dproj\n"
           "#define texRECTlod tex2Dlod\n#define FXVIEW 1\n"
           // glslang 12 makes lit()'s specular term n.h * m instead of pow(n.h, m): HLSL's definition here.
           "#define lit(nl, nh, m) float4(1.0, max((nl), 0.0), ((nl) < 0.0 || (nh) < 0.0) ? 0.0 : pow(max((nh), 0.0), (m)), 1.0)\n";
}

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
    return output;
}

}  // namespace fxview::legacy
