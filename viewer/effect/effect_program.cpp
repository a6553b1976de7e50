#include "effect/effect_program.hpp"

#include <algorithm>
#include <cstring>
#include <map>
#include <sstream>
#include <vector>

#include "effect/parser.hpp"
#include "gl/program.hpp"

namespace fxview::effect {
namespace {

GLenum gl_stage(ShaderStage stage) {
    switch (stage) {
        case ShaderStage::Vertex: return GL_VERTEX_SHADER;
        case ShaderStage::Geometry: return GL_GEOMETRY_SHADER;
        case ShaderStage::Fragment: return GL_FRAGMENT_SHADER;
    }
    return GL_VERTEX_SHADER;
}

}  // namespace

std::string assemble_stage(const Effect& effect, const Pass& pass, ShaderStage stage) {
    const ShaderBlock* block = effect.find_shader(pass.shaders.at(stage));
    if (block->complete) return block->code;
    std::string source = "#version 450 core\n";
    for (const auto& p : effect.parameters) {
        source += effect.sources.line_directive(p.where);
        source += "uniform " + p.type + " " + p.name;
        if (p.array_size > 0) source += "[" + std::to_string(p.array_size) + "]";
        source += ";\n";
    }
    source += effect.globals;
    source += effect.find_shader(pass.shaders.at(stage))->code;
    return source;
}

std::string fold_repeated_messages(const std::string& lines) {
    const std::string marker = " [technique ";
    std::vector<std::string> order;                            // the messages, first seen first
    std::map<std::string, std::vector<std::string>> contexts;  // message -> the contexts it came with
    std::istringstream in(lines);
    for (std::string line; std::getline(in, line);) {
        if (line.empty()) continue;
        const size_t at = line.rfind(marker);
        const std::string message = at == std::string::npos ? line : line.substr(0, at);
        const std::string context = at == std::string::npos ? "" : line.substr(at);
        auto& seen = contexts[message];
        if (seen.empty()) order.push_back(message);
        if (std::find(seen.begin(), seen.end(), context) == seen.end()) seen.push_back(context);
    }
    std::string out;
    for (const auto& message : order) {
        const auto& seen = contexts[message];
        if (seen.size() == 1) {
            out += message + seen.front() + "\n";
            continue;
        }
        // The technique names of the contexts, each once.
        std::vector<std::string> names;
        for (const auto& context : seen) {
            const size_t begin = marker.size(), end = context.find(',', begin);
            const std::string name = context.substr(begin, end == std::string::npos ? std::string::npos : end - begin);
            if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
        }
        std::string list;
        for (const auto& name : names) list += (list.empty() ? "" : ", ") + name;
        out += message + (names.size() == 1 ? " [technique " : " [techniques ") + list + "]\n";
    }
    return out;
}

CompiledTechnique compile_technique(const Effect& effect, const Technique& technique) {
    CompiledTechnique compiled;
    compiled.technique = &technique;
    std::string errors;
    std::map<std::string, std::shared_ptr<gl::Program>> linked;  // by the stages' sources
    for (const auto& pass : technique.passes) {
        std::vector<gl::ShaderSource> stages;
        for (const auto& [stage, name] : pass.shaders)
            stages.push_back({gl_stage(stage), assemble_stage(effect, pass, stage), name});
        CompiledPass compiled_pass;
        compiled_pass.pass = &pass;
        compiled_pass.row_vectors = effect.row_vectors;
        if (pass.states.draw_scene) {  // drawn by fxview's plain shader: no program of its own
            compiled.passes.push_back(std::move(compiled_pass));
            continue;
        }
        // A translated stage that failed to translate fails its technique with the translator's messages.
        std::string translation;
        for (const auto& [stage, name] : pass.shaders) translation += effect.find_shader(name)->translation_errors;
        if (!translation.empty()) {
            std::istringstream lines(translation);
            for (std::string line; std::getline(lines, line);)
                if (!line.empty()) errors += line + " [technique " + technique.name + ", pass " + pass.name + "]\n";
            continue;
        }
        std::string key;
        for (const auto& stage : stages) key += std::to_string(stage.stage) + '\n' + stage.source + '\0';
        try {
            std::shared_ptr<gl::Program>& program = linked[key];
            if (!program) program = std::make_shared<gl::Program>(gl::link_program(stages));
            compiled_pass.program = program;
        } catch (const gl::ShaderError& error) {
            // Each driver message becomes "file:line: message (technique, pass)"; messages without a
            // line (link errors) are given the pass's location.
            const std::string context =
                " [technique " + technique.name + ", pass " + pass.name + ", " + error.label + ": " + error.summary + "]";
            std::istringstream lines(effect.sources.map_compiler_log(error.log));
            for (std::string line; std::getline(lines, line);) {
                if (line.empty()) continue;
                const bool located = line.find(": ") != std::string::npos && effect.sources.has_file_prefix(line);
                errors += (located ? line : pass.where.str() + ": " + line) + context + "\n";
            }
            if (error.log.empty()) errors += pass.where.str() + ": " + error.what() + context + "\n";
            continue;
        }
        const GLuint program = compiled_pass.program->get();
        GLint count = 0;
        glGetProgramInterfaceiv(program, GL_UNIFORM, GL_ACTIVE_RESOURCES, &count);
        for (GLint i = 0; i < count; ++i) {
            const GLenum properties[] = {GL_TYPE, GL_LOCATION, GL_ARRAY_SIZE, GL_BLOCK_INDEX, GL_NAME_LENGTH};
            GLint results[5] = {};
            glGetProgramResourceiv(program, GL_UNIFORM, static_cast<GLuint>(i), 5, properties, 5, nullptr, results);
            if (results[3] != -1) continue;  // member of a uniform block: bound by the block
            std::string name(static_cast<size_t>(results[4]), '\0');
            glGetProgramResourceName(program, GL_UNIFORM, static_cast<GLuint>(i), results[4], nullptr, name.data());
            name.resize(name.find('\0') == std::string::npos ? name.size() : name.find('\0'));
            if (const size_t bracket = name.find('['); bracket != std::string::npos) name.resize(bracket);
            const Parameter* parameter = effect.find_parameter(name);
            // SPIRV-Cross prefixes names that are reserved in GLSL with '_'.
            if (!parameter && effect.legacy && name.size() > 1 && name[0] == '_') parameter = effect.find_parameter(name.substr(1));
            if (!parameter)
                throw EffectError(pass.where, "pass " + pass.name + ": uniform '" + name +
                                                  "' is declared inside a shader block; declare it at the top level of the effect");
            BoundUniform uniform{results[1], static_cast<GLenum>(results[0]), results[2], parameter, -1};
            if (is_sampler_type(parameter->type)) {
                const auto& targets = pass.states.render_targets;
                if (std::find(targets.begin(), targets.end(), parameter->texture) != targets.end())
                    throw EffectError(pass.where, "pass " + pass.name + " samples " + parameter->texture +
                                                      " through " + parameter->name + " while rendering into it");
                uniform.texture_unit = compiled_pass.texture_units++;
                glProgramUniform1i(program, uniform.location, uniform.texture_unit);
            }
            compiled_pass.uniforms.push_back(uniform);
        }
        for (const auto& [stage, name] : pass.shaders) {
            const ShaderBlock* block = effect.find_shader(name);
            if (!block->uniform_block) continue;
            BoundUniformBlock bound;
            bound.layout = &*block->uniform_block;
            for (const auto& member : bound.layout->members) bound.parameters.push_back(effect.find_parameter(member.parameter));
            bound.buffer = gl::create_buffer();
            glNamedBufferData(bound.buffer.get(), std::max<GLsizeiptr>(16, bound.layout->size), nullptr, GL_DYNAMIC_DRAW);
            compiled_pass.blocks.push_back(std::move(bound));
        }
        compiled.passes.push_back(std::move(compiled_pass));
    }
    if (!errors.empty()) throw EffectError(technique.where, errors, EffectError::Lines{});
    return compiled;
}

namespace {

// A parameter's current value as floats in fxview's convention (matrices column-major), or empty.
std::vector<float> current_value(const Parameter& p, const ParameterValues& values, const FrameContext& frame, int components) {
    if (!p.semantic.empty()) {
        std::vector<float> data = semantic_value(p.semantic, frame, components);
        data.resize(static_cast<size_t>(components));
        return data;
    }
    const auto found = values.numbers.find(p.name);
    if (found == values.numbers.end()) return {};
    return {found->second.begin(), found->second.end()};
}

}  // namespace

std::vector<std::byte> pack_uniform_block(const UniformBlockLayout& layout, const std::vector<const Parameter*>& parameters,
                                          const ParameterValues& values, const FrameContext& frame, bool row_vectors) {
    std::vector<std::byte> bytes(layout.size);
    auto put = [&](std::uint32_t offset, float value, UniformBlockMember::Kind kind) {
        if (offset + 4 > bytes.size()) return;
        if (kind == UniformBlockMember::Kind::Float) {
            std::memcpy(bytes.data() + offset, &value, 4);
        } else if (kind == UniformBlockMember::Kind::Int) {
            const std::int32_t i = static_cast<std::int32_t>(std::clamp(value, -2147483648.0f, 2147483520.0f));
            std::memcpy(bytes.data() + offset, &i, 4);
        } else {
            const std::uint32_t u = static_cast<std::uint32_t>(std::clamp(value, 0.0f, 4294967040.0f));
            std::memcpy(bytes.data() + offset, &u, 4);
        }
    };
    for (size_t m = 0; m < layout.members.size(); ++m) {
        const UniformBlockMember& member = layout.members[m];
        const Parameter* p = parameters[m];
        if (!p) continue;
        const int components = component_count(p->type);
        if (components == 0) continue;
        const int count = std::max(1, member.array_size);
        const std::vector<float> data = current_value(*p, values, frame, components);
        if (data.size() < static_cast<size_t>(components)) continue;
        for (int element = 0; element < count && static_cast<size_t>((element + 1) * components) <= data.size(); ++element) {
            const float* v = data.data() + element * components;
            const std::uint32_t base = member.offset + static_cast<std::uint32_t>(element) * member.array_stride;
            if (member.columns == 1) {
                for (int k = 0; k < std::min(member.vector_size, components); ++k) put(base + 4u * static_cast<std::uint32_t>(k), v[k], member.kind);
                continue;
            }
            // Our matrix M (column-major, n x n) and SPIR-V's S: glslang gives an HLSL matrix's rows
            // as S's columns, so S = M^T of the HLSL matrix. Row-vector files hold H = M^T (S = M),
            // column-vector files H = M (S = M^T).
            const int n = components == 16 ? 4 : components == 9 ? 3 : 2;
            for (int r = 0; r < member.vector_size && r < n; ++r)
                for (int c = 0; c < member.columns && c < n; ++c) {
                    const float s = row_vectors ? v[c * n + r] : v[r * n + c];
                    const std::uint32_t at = member.row_major ? base + static_cast<std::uint32_t>(r) * member.matrix_stride + 4u * static_cast<std::uint32_t>(c)
                                                              : base + static_cast<std::uint32_t>(c) * member.matrix_stride + 4u * static_cast<std::uint32_t>(r);
                    put(at, s, member.kind);
                }
        }
    }
    return bytes;
}

void bind_uniforms(const CompiledPass& pass, const ParameterValues& values, const FrameContext& frame) {
    for (const auto& block : pass.blocks) {
        const std::vector<std::byte> bytes = pack_uniform_block(*block.layout, block.parameters, values, frame, pass.row_vectors);
        glNamedBufferSubData(block.buffer.get(), 0, static_cast<GLsizeiptr>(bytes.size()), bytes.data());
        glBindBufferBase(GL_UNIFORM_BUFFER, block.layout->binding, block.buffer.get());
    }
    const GLuint program = pass.program->get();
    for (const auto& uniform : pass.uniforms) {
        const Parameter& p = *uniform.parameter;
        const int components = component_count(p.type);
        if (components == 0) continue;  // samplers: texture units come with texture support
        std::vector<float> data;
        if (!p.semantic.empty()) {
            data = semantic_value(p.semantic, frame, components);
            data.resize(static_cast<size_t>(components));
        } else {
            const auto found = values.numbers.find(p.name);
            if (found == values.numbers.end()) continue;
            data.assign(found->second.begin(), found->second.end());
        }
        const GLsizei count = std::max(1, p.array_size);
        if (data.size() < static_cast<size_t>(components * count)) continue;
        const bool unsigned_type = p.type == "uint" || p.type.rfind("uvec", 0) == 0;
        const bool integer = p.type == "int" || p.type.rfind("ivec", 0) == 0 || p.type == "bool" || p.type.rfind("bvec", 0) == 0;
        if (unsigned_type) {
            const PFNGLPROGRAMUNIFORM1UIVPROC setters[4] = {glProgramUniform1uiv, glProgramUniform2uiv, glProgramUniform3uiv,
                                                            glProgramUniform4uiv};
            std::vector<GLuint> uints;
            for (float v : data) uints.push_back(static_cast<GLuint>(std::max(0.0f, v)));
            setters[components - 1](program, uniform.location, count, uints.data());
            continue;
        }
        if (integer) {  // bool uniforms take the integer setters
            const PFNGLPROGRAMUNIFORM1IVPROC setters[4] = {glProgramUniform1iv, glProgramUniform2iv, glProgramUniform3iv,
                                                           glProgramUniform4iv};
            const std::vector<GLint> ints(data.begin(), data.end());
            setters[components - 1](program, uniform.location, count, ints.data());
            continue;
        }
        switch (components) {
            case 1: glProgramUniform1fv(program, uniform.location, count, data.data()); break;
            case 2: glProgramUniform2fv(program, uniform.location, count, data.data()); break;
            case 3: glProgramUniform3fv(program, uniform.location, count, data.data()); break;
            case 4:
                if (p.type == "mat2") glProgramUniformMatrix2fv(program, uniform.location, count, GL_FALSE, data.data());
                else glProgramUniform4fv(program, uniform.location, count, data.data());
                break;
            case 9: glProgramUniformMatrix3fv(program, uniform.location, count, GL_FALSE, data.data()); break;
            case 16: glProgramUniformMatrix4fv(program, uniform.location, count, GL_FALSE, data.data()); break;
        }
    }
}

}  // namespace fxview::effect
