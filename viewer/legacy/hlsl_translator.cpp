#include "legacy/hlsl_translator.hpp"

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>
#include <spirv_cross/spirv_glsl.hpp>

#include <algorithm>
#include <cctype>
#include <memory>
#include <sstream>

#include "core/text.hpp"
#include "legacy/glslang_process.hpp"

namespace fxview::legacy {
namespace {

using effect::ShaderStage;

EShLanguage glslang_stage(ShaderStage stage) {
    return stage == ShaderStage::Vertex ? EShLangVertex : stage == ShaderStage::Geometry ? EShLangGeometry : EShLangFragment;
}

const EShMessages kMessages = static_cast<EShMessages>(EShMsgSpvRules | EShMsgVulkanRules | EShMsgReadHlsl | EShMsgHlslDX9Compatible);

// glslang's "ERROR: 0:12: 'x' : undeclared identifier" lines as "file:line: error: 'x' : undeclared identifier".
std::string map_log(const std::string& log, int file_lines, const effect::SourceLocation& entry,
                    const std::function<effect::SourceLocation(int)>& locate, const std::string& program) {
    const std::string in = program.empty() ? "" : " (while compiling the " + program + ")";
    std::string out;
    std::istringstream lines(log);
    for (std::string line; std::getline(lines, line);) {
        if (line.rfind("ERROR: ", 0) != 0) continue;
        std::string rest = line.substr(7);
        // "0:12: message" (string index, line)
        const size_t colon = rest.find(':');
        const size_t second = colon == std::string::npos ? std::string::npos : rest.find(':', colon + 1);
        int number = 0;
        if (second != std::string::npos) {
            const std::string digits = rest.substr(colon + 1, second - colon - 1);
            if (!digits.empty() && std::all_of(digits.begin(), digits.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); }))
                number = std::stoi(digits.substr(0, 9));
        }
        if (number == 0) {
            if (rest.find("compilation errors") != std::string::npos || rest.find("compilation terminated") != std::string::npos) continue;
            out += entry.str() + ": error: " + excerpt(rest, 300) + in + "\n";
            continue;
        }
        std::string message = rest.substr(second + 1);
        message.erase(0, message.find_first_not_of(' '));
        const effect::SourceLocation where = number > file_lines ? entry : locate(number);
        out += where.str() + ": error: " + excerpt(message, 300) + (number > file_lines ? " (in the entry generated for the compile statement)" : in) + "\n";
    }
    return out;
}

// Vertex inputs by semantic: fxview's meshes give position 0, normal 1, tangent 2, bitangent 3,
// uv 4 (docs/legacy-effects.md); COLOR reads a constant white, anything else zero.
int attribute_location(const std::string& semantic, int& next_free) {
    if (semantic == "POSITION0" || semantic == "SV_POSITION0") return 0;
    if (semantic == "NORMAL0") return 1;
    if (semantic == "TANGENT0" || semantic == "TEXCOORD6") return 2;
    if (semantic == "BINORMAL0" || semantic == "BITANGENT0" || semantic == "TEXCOORD7") return 3;
    if (semantic.rfind("TEXCOORD", 0) == 0) return 4;
    if (semantic == "COLOR0" || semantic == "DIFFUSE0") return 5;
    return next_free < 15 ? next_free++ : 15;
}

std::string semantic_of(const spirv_cross::CompilerGLSL& compiler, spirv_cross::ID id) {
    return canonical_semantic(compiler.get_decoration_string(id, spv::DecorationUserSemantic));
}

effect::UniformBlockLayout reflect_block(const spirv_cross::CompilerGLSL& compiler, const spirv_cross::Resource& block, std::uint32_t binding) {
    effect::UniformBlockLayout layout;
    layout.binding = binding;
    const spirv_cross::SPIRType& type = compiler.get_type(block.base_type_id);
    layout.size = static_cast<std::uint32_t>(compiler.get_declared_struct_size(type));
    for (std::uint32_t i = 0; i < type.member_types.size(); ++i) {
        const spirv_cross::SPIRType& member_type = compiler.get_type(type.member_types[i]);
        effect::UniformBlockMember member;
        member.parameter = compiler.get_member_name(block.base_type_id, i);
        member.offset = compiler.type_struct_member_offset(type, i);
        member.vector_size = static_cast<int>(member_type.vecsize);
        member.columns = static_cast<int>(member_type.columns);
        member.kind = member_type.basetype == spirv_cross::SPIRType::Int ? effect::UniformBlockMember::Kind::Int
                    : member_type.basetype == spirv_cross::SPIRType::UInt || member_type.basetype == spirv_cross::SPIRType::Boolean
                        ? effect::UniformBlockMember::Kind::UInt
                        : effect::UniformBlockMember::Kind::Float;
        if (!member_type.array.empty()) {
            member.array_size = static_cast<int>(member_type.array[0]);
            member.array_stride = compiler.type_struct_member_array_stride(type, i);
        }
        if (member.columns > 1) {
            member.matrix_stride = compiler.type_struct_member_matrix_stride(type, i);
            member.row_major = compiler.has_member_decoration(block.base_type_id, i, spv::DecorationRowMajor);
        }
        if (member_type.basetype == spirv_cross::SPIRType::Struct) continue;  // structs are no parameters
        layout.members.push_back(std::move(member));
    }
    return layout;
}

void make_builtin(spirv_cross::CompilerGLSL& compiler, spirv_cross::ID id, spv::BuiltIn builtin) {
    compiler.unset_decoration(id, spv::DecorationLocation);
    compiler.set_decoration(id, spv::DecorationBuiltIn, builtin);
}

// glslang: the stage's HLSL to legalised SPIR-V, or its messages at file:line; once per entry.
const SpirvCache::Entry& compile_to_spirv(const StageRequest& request, int file_lines,
                                          const std::function<effect::SourceLocation(int)>& locate, SpirvCache& cache) {
    const std::string key = std::to_string(static_cast<int>(request.stage)) + "\n" + request.code;
    if (const auto found = cache.entries.find(key); found != cache.entries.end()) return found->second;
    SpirvCache::Entry& entry = cache.entries[key];
    const EShLanguage stage = glslang_stage(request.stage);
    glslang::TShader shader(stage);
    const char* text = request.code.c_str();
    const int length = static_cast<int>(request.code.size());
    shader.setStringsWithLengths(&text, &length, 1);
    shader.setEntryPoint(request.entry.c_str());
    shader.setEnvInput(glslang::EShSourceHlsl, stage, glslang::EShClientVulkan, 100);
    shader.setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_0);
    shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_0);
    shader.setEnvTargetHlslFunctionality1();  // keeps the semantics as UserSemantic decorations
    shader.setAutoMapLocations(true);
    shader.setAutoMapBindings(true);
    if (!shader.parse(GetDefaultResources(), 100, false, kMessages)) {
        entry.errors = map_log(shader.getInfoLog(), file_lines, request.where, locate, request.program);
        if (entry.errors.empty()) entry.errors = request.where.str() + ": error: the compiler refused the program\n";
        return entry;
    }
    glslang::TProgram program;
    program.addShader(&shader);
    if (!program.link(kMessages) || !program.mapIO()) {
        entry.errors = map_log(program.getInfoLog(), file_lines, request.where, locate, request.program);
        if (entry.errors.empty()) entry.errors = request.where.str() + ": error: the program does not link\n";
        return entry;
    }
    glslang::SpvOptions options;
    options.disableOptimizer = false;  // HLSL needs the legalisation passes (samplers passed to functions, ...)
    spv::SpvBuildLogger logger;
    glslang::GlslangToSpv(*program.getIntermediate(stage), entry.spirv, &logger, &options);
    return entry;
}

}  // namespace

std::string canonical_semantic(const std::string& semantic) {
    std::string s = semantic;
    for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    if (s.rfind("SV_TARGET", 0) == 0) s = "COLOR" + s.substr(9);
    if (s == "SV_DEPTH") s = "DEPTH";
    if (s.empty() || !std::isdigit(static_cast<unsigned char>(s.back()))) s += "0";
    return s;
}

TranslatedPass translate_pass(const std::vector<StageRequest>& stages, int file_lines,
                              const std::function<effect::SourceLocation(int)>& locate, SpirvCache& cache) {
    ensure_glslang_process();
    TranslatedPass result;
    struct Compiled {
        const StageRequest* request;
        std::unique_ptr<spirv_cross::CompilerGLSL> compiler;
    };
    std::vector<Compiled> compiled;
    for (const auto& request : stages) {
        if (request.stage == ShaderStage::Geometry) {
            result.errors += request.where.str() + ": error: geometry programs of legacy effects are not supported\n";
            continue;
        }
        const SpirvCache::Entry& entry = compile_to_spirv(request, file_lines, locate, cache);
        if (!entry.errors.empty()) {
            result.errors += entry.errors;
            continue;
        }
        std::vector<unsigned> spirv = entry.spirv;
        try {
            auto compiler = std::make_unique<spirv_cross::CompilerGLSL>(std::move(spirv));
            spirv_cross::CompilerGLSL::Options glsl = compiler->get_common_options();
            glsl.version = 450;
            glsl.es = false;
            glsl.vulkan_semantics = false;
            compiler->set_common_options(glsl);
            compiled.push_back({&request, std::move(compiler)});
        } catch (const std::exception& error) {
            result.errors += request.where.str() + ": error: " + excerpt(error.what(), 300) + "\n";
        }
    }
    if (!result.errors.empty()) return result;

    // Varyings: the vertex outputs' semantics give the locations the fragment inputs look up.
    std::map<std::string, std::uint32_t> varyings;
    for (auto& [request, compiler] : compiled) {
        if (request->stage != ShaderStage::Vertex) continue;
        const auto resources = compiler->get_shader_resources();
        int next_free = 6;
        for (const auto& input : resources.stage_inputs)
            compiler->set_decoration(input.id, spv::DecorationLocation, static_cast<std::uint32_t>(attribute_location(semantic_of(*compiler, input.id), next_free)));
        for (const auto& output : resources.stage_outputs) {
            const std::string semantic = semantic_of(*compiler, output.id);
            if (compiler->has_decoration(output.id, spv::DecorationBuiltIn)) continue;
            if (semantic == "POSITION0" || semantic == "HPOS0") {  // DX9's POSITION output is SV_Position
                make_builtin(*compiler, output.id, spv::BuiltInPosition);
                continue;
            }
            const auto location = varyings.emplace(semantic, static_cast<std::uint32_t>(varyings.size())).first->second;
            compiler->set_decoration(output.id, spv::DecorationLocation, location);
        }
    }
    for (auto& [request, compiler] : compiled) {
        if (request->stage != ShaderStage::Fragment) continue;
        const auto resources = compiler->get_shader_resources();
        for (const auto& input : resources.stage_inputs) {
            if (compiler->has_decoration(input.id, spv::DecorationBuiltIn)) continue;
            const std::string semantic = semantic_of(*compiler, input.id);
            if (semantic == "POSITION0" || semantic == "VPOS0" || semantic == "WPOS0") {
                make_builtin(*compiler, input.id, spv::BuiltInFragCoord);
                continue;
            }
            const auto found = varyings.find(semantic);
            if (found == varyings.end()) {
                result.errors += request->where.str() + ": error: the fragment program reads " + semantic +
                                 ", which the vertex program of the pass does not write\n";
                continue;
            }
            compiler->set_decoration(input.id, spv::DecorationLocation, found->second);
        }
        for (const auto& output : resources.stage_outputs) {
            if (compiler->has_decoration(output.id, spv::DecorationBuiltIn)) continue;
            const std::string semantic = semantic_of(*compiler, output.id);
            if (semantic == "DEPTH0") {
                make_builtin(*compiler, output.id, spv::BuiltInFragDepth);
                continue;
            }
            std::uint32_t index = 0;
            if (semantic.rfind("COLOR", 0) == 0) index = static_cast<std::uint32_t>(semantic.back() - '0');
            compiler->set_decoration(output.id, spv::DecorationLocation, index);
        }
    }
    if (!result.errors.empty()) return result;

    for (auto& [request, compiler] : compiled) {
        try {
            const auto resources = compiler->get_shader_resources();
            TranslatedStage stage;
            std::uint32_t binding = request->stage == ShaderStage::Vertex ? 0 : 1;
            for (const auto& block : resources.uniform_buffers) {
                if (block.name != "$Global") {
                    result.errors += request->where.str() + ": error: constant buffer " + excerpt(block.name) + " is not supported (declare the parameters as globals)\n";
                    continue;
                }
                // Each stage gets a block of its own: the two never have to agree on a layout.
                compiler->set_name(block.base_type_id, request->stage == ShaderStage::Vertex ? "fxview_VertexGlobals" : "fxview_FragmentGlobals");
                compiler->set_decoration(block.id, spv::DecorationBinding, binding);
                compiler->unset_decoration(block.id, spv::DecorationDescriptorSet);
                stage.uniform_block = reflect_block(*compiler, block, binding);
            }
            for (const auto& sampler : resources.sampled_images) compiler->unset_decoration(sampler.id, spv::DecorationDescriptorSet);
            stage.glsl = compiler->compile();
            result.stages[request->stage] = std::move(stage);
        } catch (const std::exception& error) {
            result.errors += request->where.str() + ": error: " + excerpt(error.what(), 300) + "\n";
        }
    }
    return result;
}

}  // namespace fxview::legacy
