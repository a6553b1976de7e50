#include "render/effect_resources.hpp"
#include "render/environment_maps.hpp"
#include "render/measured_brdf_texture.hpp"

#include <cmath>
#include <cstdlib>
#include <algorithm>
#include <filesystem>

#include "effect/parser.hpp"
#include "texture/placeholder.hpp"

#include "core/text.hpp"
#include "gl/texture_upload.hpp"
#include "spectral/fourier_table.hpp"
#include "spectral/library.hpp"
#include "texture/texture_file.hpp"

namespace fxview::render {

namespace fs = std::filesystem;
using texture::TextureData;
using texture::TextureType;

std::string resolve_texture_path(const std::string& file, const std::string& effect_path,
                                 const std::vector<std::string>& texture_dirs) {
    std::vector<fs::path> candidates;
    if (file.size() > 1024) throw Error("texture file name of " + std::to_string(file.size()) + " characters (at most 1024)");
    if (fs::path(file).is_absolute()) candidates.push_back(file);
    else {
        candidates.push_back(fs::path(effect_path).parent_path() / file);
        for (const auto& dir : texture_dirs) candidates.push_back(fs::path(dir) / file);
    }
    std::error_code error;
    for (const auto& candidate : candidates)
        if (fs::is_regular_file(candidate, error)) return candidate.lexically_normal().string();
    std::string searched;
    for (const auto& candidate : candidates) searched += (searched.empty() ? "" : ", ") + candidate.parent_path().string();
    for (const auto& candidate : candidates)  // there, but a device or a folder
        if (fs::exists(candidate, error)) throw Error(excerpt(candidate.string(), 200) + ": " + not_a_file(candidate.string()) + " (a texture file was expected)");
    throw Error("texture file '" + excerpt(file, 200) + "' not found (searched " + excerpt(searched, 400) + ")");
}

namespace {

// What a texture occupies once stored in `format` (all faces and levels).
std::int64_t stored_bytes(const TextureData& data, texture::PixelFormat format) {
    std::int64_t bytes = 0;
    for (const auto& face : data.faces)
        for (const auto& level : face) bytes += static_cast<std::int64_t>(texture::level_size(format, level.width, level.height, level.depth));
    return bytes;
}

// Loads a texture resource's file(s) into the shape its declaration asks for.
TextureData load_resource(const effect::TextureResource& resource, const std::vector<std::string>& paths, const ResourceLimits& limits) {
    if (resource.type == TextureType::Cube && paths.size() == 6) {
        TextureData cube;
        cube.type = TextureType::Cube;
        for (const auto& path : paths) {
            TextureData face = texture::load_texture_file(path, limits);
            if (face.width() != face.height()) throw Error(path + ": cube faces must be square");
            if (!cube.faces.empty() && (face.width() != cube.width() || face.format != cube.format))
                throw Error(path + ": cube faces must share one size and format");
            cube.format = face.format;
            cube.source += (cube.source.empty() ? "" : ";") + path;
            cube.faces.push_back(std::move(face.faces[0]));
            // Checked face by face: six faces each within budget can still exceed it together.
            check_limit(limits, "texture-bytes", stored_bytes(cube, cube.format), path, "cube map, with this face,");
        }
        return cube;
    }
    if (paths.size() != 1)
        throw Error("texture " + resource.name + " names " + std::to_string(paths.size()) +
                    " files; only a cube map takes six");
    if (resource.type == TextureType::Tex3D && is_measured_brdf_file(paths[0])) return load_measured_brdf_texture(paths[0], limits);
    TextureData data = texture::load_texture_file(paths[0], limits);
    switch (resource.type) {
        case TextureType::Cube: return data.type == TextureType::Cube ? data : texture::split_cube_cross(data);
        case TextureType::Tex1D: return texture::as_1d(data);
        case TextureType::Tex3D:
            if (data.type == TextureType::Tex3D) return data;  // a DDS volume
            if (resource.depth == 0)
                throw Error(paths[0] + ": a 3D texture from an image needs a Depth annotation (slices stacked top to bottom)");
            return texture::as_3d(data, resource.depth);
        case TextureType::Tex2D:
            if (data.type != TextureType::Tex2D)
                throw Error(paths[0] + ": holds a cube or volume texture, but " + resource.name + " is 2D");
            return data;
    }
    return data;
}

texture::PixelFormat storage_format(effect::TextureStorage storage, texture::PixelFormat native) {
    switch (storage) {
        case effect::TextureStorage::Unorm8: return texture::PixelFormat::RGBA8;
        case effect::TextureStorage::Float16: return texture::PixelFormat::RGBA16F;
        case effect::TextureStorage::Float32: return texture::PixelFormat::RGBA32F;
        case effect::TextureStorage::Native: return native;
    }
    return native;
}

}  // namespace

std::string spectral_library_path() {
    const char* override_dir = std::getenv("FXVIEW_SPECTRA_DIR");
    return std::string(override_dir ? override_dir : FXVIEW_SOURCE_SPECTRA_DIR) + "/library.txt";
}

namespace {

spectral::PackedTexture make_generated(const effect::TextureResource& resource) {
    const std::string& what = resource.files[0];
    const texture::PixelFormat format = storage_format(resource.storage, texture::PixelFormat::RGBA32F);
    if (what == "spectral:cmf") return spectral::cmf_texture(spectral::load_observer("1931"), spectral::load_observer("1964"), format);
    if (what == "spectral:library") return spectral::pack_spectra(spectral::load_library(spectral_library_path()).spectra(), format);
    return spectral::fourier_table(spectral::load_library(spectral_library_path()).spectra(), spectral::load_observer("1931"),
                                   spectral::load_observer("1964"));
}

}  // namespace

const texture::TextureData* EffectResources::cpu_copy(const std::string& texture_name) const {
    const auto found = cpu_copies_.find(texture_name);
    return found == cpu_copies_.end() ? nullptr : &found->second;
}

const spectral::PackedTexture* EffectResources::generated(const std::string& texture_name) const {
    const std::lock_guard lock(generated_mutex_);
    if (const auto found = generated_.find(texture_name); found != generated_.end()) return &found->second;
    const auto resource = generated_resources_.find(texture_name);
    if (resource == generated_resources_.end()) return nullptr;
    return &generated_.emplace(texture_name, make_generated(*resource->second)).first->second;
}

const spectral::PackedTexture* EffectResources::generated_resource(const std::string& resource) const {
    const spectral::PackedTexture* found = nullptr;
    for (const auto& [name, texture] : generated_resources_) {
        if (texture->files.empty() || texture->files[0] != resource) continue;
        const spectral::PackedTexture* packed = generated(name);
        // The float copy where the effect has an 8-bit one besides (spectral.glsl's CmfBytes).
        if (!found || packed->texture.format == texture::PixelFormat::RGBA32F) found = packed;
    }
    return found;
}

const GpuTexture* EffectResources::acquire(const std::string& texture_name) {
    if (const auto environment = environment_resources_.find(texture_name); environment != environment_resources_.end())
        return environment_ ? environment_->texture(environment->second) : nullptr;
    if (!textures_.count(texture_name) && generated_resources_.count(texture_name)) {
        const spectral::PackedTexture& packed = *generated(texture_name);
        GpuTexture gpu;
        gpu.texture = gl::upload_texture(packed.texture, {false, false});
        gpu.type = packed.texture.type;
        gpu.format = packed.texture.format;
        gpu.width = packed.texture.width();
        gpu.height = packed.texture.height();
        gpu.source = generated_resources_.at(texture_name)->files[0];
        textures_.emplace(texture_name, std::move(gpu));
    }
    return find(texture_name);
}

std::string resolve_legacy_texture_path(const std::string& file, const std::string& effect_path,
                                        const std::vector<std::string>& texture_dirs) {
    // Windows paths (..\Media\Textures\Snow.dds): as written with '/', else the file name alone.
    std::string slashed = file;
    std::replace(slashed.begin(), slashed.end(), '\\', '/');
    try {
        return resolve_texture_path(slashed, effect_path, texture_dirs);
    } catch (const Error&) {
        const std::string name = fs::path(slashed).filename().string();
        if (name.empty() || name == slashed) throw;
        try {
            return resolve_texture_path(name, effect_path, texture_dirs);
        } catch (const Error&) {
            throw Error("texture file '" + excerpt(file, 200) + "' not found (nor " + excerpt(name, 200) + " next to the effect or in the texture folders)");
        }
    }
}

void EffectResources::add_placeholder(const effect::TextureResource& resource, const std::string& problem) {
    const std::string file = resource.files.empty() ? std::string() : resource.files.front();
    TextureData data = texture::placeholder_texture(resource.type, resource.name, file);
    std::string sampler = resource.name;  // what --set takes: a sampler reading the texture
    for (const auto& p : effect_.parameters)
        if (effect::is_sampler_type(p.type) && p.texture == resource.name) sampler = p.name;
    warnings_.push_back(resource.where.str() + ": warning: texture " + resource.name + " " + excerpt(problem, 300) + "; showing a " +
                        texture::placeholder_kind(resource.type, resource.name, file) + " instead (replace it with --set " + sampler + "=FILE)");
    add_texture(resource.name, std::move(data), false);
}

void EffectResources::add_texture(const std::string& name, TextureData data, bool srgb) {
    GpuTexture gpu;
    gpu.texture = gl::upload_texture(data, {srgb, true});
    gpu.type = data.type;
    gpu.format = data.format;
    gpu.width = data.width();
    gpu.height = data.height();
    GLint levels = 1;  // upload_texture generates a mip chain for single-level files
    glGetTextureParameteriv(gpu.texture.get(), GL_TEXTURE_IMMUTABLE_LEVELS, &levels);
    gpu.levels = std::max(1, static_cast<int>(levels));
    gpu.generated_levels = gpu.levels > data.levels();
    gpu.source = data.source;
    textures_.emplace(name, std::move(gpu));
    cpu_copies_.emplace(name, std::move(data));
}

EffectResources::EffectResources(const effect::Effect& effect, const effect::ParameterValues& values,
                                 const std::vector<std::string>& texture_dirs)
    : effect_(effect) {
    for (const auto& resource : effect.textures) {
        if (resource.render_target) continue;
        std::vector<std::string> legacy_paths;  // legacy effects: where their (Windows-style) names were found
        try {
            if (resource.files.size() == 1 && resource.files[0].rfind("environment:", 0) == 0) {
                if (!EnvironmentMaps::is_resource_name(resource.files[0]))
                    throw effect::EffectError(resource.where, "unknown environment texture '" + resource.files[0] +
                                                                  "' (environment:specular, environment:irradiance, environment:dfg, environment:lobe-mass, environment:spectral-weights, environment:spectral-irradiance, environment:spectral-lobe-weights, environment:spectral-discs, environment:spectra or environment:fourier)");
                environment_resources_.emplace(resource.name, resource.files[0]);
                continue;
            }
            if (resource.files.size() == 1 && resource.files[0].rfind("spectral:", 0) == 0) {
                // Checked now, made when a pass first samples it (acquire) or a CPU reference reads it
                // (generated): the thin-film transforms take a fifth of a second that techniques not
                // using them should not pay.
                const std::string& what = resource.files[0];
                if (what != "spectral:cmf" && what != "spectral:library" && what != "spectral:fourier")
                    throw effect::EffectError(resource.where, "unknown generated texture '" + what +
                                                                  "' (spectral:cmf, spectral:library or spectral:fourier)");
                // Float only: the transforms are signed and need more than 8 bits.
                if (what == "spectral:fourier" && storage_format(resource.storage, texture::PixelFormat::RGBA32F) != texture::PixelFormat::RGBA32F)
                    throw effect::EffectError(resource.where, "spectral:fourier is stored as 32F only");
                generated_resources_.emplace(resource.name, &resource);
                continue;
            }
            // `--set Sampler=file` replaces the file of the texture the sampler reads.
            auto override_file = values.textures.find(resource.name);
            for (const auto& p : effect.parameters)
                if (override_file == values.textures.end() && effect::is_sampler_type(p.type) && p.texture == resource.name)
                    override_file = values.textures.find(p.name);
            if (effect.legacy && override_file == values.textures.end()) {
                // A legacy effect opens even when its texture files are missing (docs/legacy-effects.md).
                std::string problem;
                if (resource.files.empty()) problem = "has no file";
                for (const auto& file : resource.files) {
                    try {
                        legacy_paths.push_back(resolve_legacy_texture_path(file, effect.path, texture_dirs));
                        effect.access.require(legacy_paths.back(), "texture file");
                    } catch (const std::exception& error) {
                        problem = error.what();
                        break;
                    }
                }
                if (!problem.empty()) {
                    add_placeholder(resource, problem);
                    continue;
                }
            }
            std::vector<std::string> paths;
            // `--set Sampler=file` replaces the file of the sampler's own texture.
            std::error_code error;
            if (override_file != values.textures.end()) {
                if (!fs::is_regular_file(override_file->second, error))
                    throw Error(excerpt(override_file->second, 200) + ": " + not_a_file(override_file->second) + " (a texture file was expected)");
                paths.push_back(override_file->second);
            } else if (!legacy_paths.empty()) {
                paths = legacy_paths;
            } else {
                for (const auto& file : resource.files) paths.push_back(resolve_texture_path(file, effect.path, texture_dirs));
            }
            for (const auto& path : paths) effect.access.require(path, "texture file");
            // A texture may use what is left of the effect's budget, so that a file too large for it
            // is refused from its header, before it is decoded.
            const std::int64_t left = effect.limits.effect_texture_bytes - file_texture_bytes_;
            ResourceLimits limits = effect.limits;
            limits.texture_bytes = std::min(limits.texture_bytes, left);
            TextureData data;
            try {
                data = load_resource(resource, paths, limits);
            } catch (const BudgetError& error) {
                if (effect.legacy) {
                    add_placeholder(resource, error.what());
                    continue;
                }
                if (left >= effect.limits.texture_bytes) throw;
                throw BudgetError(paths[0] + ": the effect's textures would exceed the budget effect-texture-bytes = " +
                                  std::to_string(effect.limits.effect_texture_bytes) + " (" + std::to_string(file_texture_bytes_) +
                                  " used by the textures before this one; raise it with --limit effect-texture-bytes=N)");
            }
            // The stored size (after conversion, e.g. 8-bit to float) counts too; checked before converting.
            const texture::PixelFormat stored = storage_format(resource.storage, data.format);
            const std::int64_t bytes = stored_bytes(data, stored);
            check_limit(effect.limits, "texture-bytes", bytes, data.source, "stored texture of");
            file_texture_bytes_ += bytes;
            check_limit(effect.limits, "effect-texture-bytes", file_texture_bytes_, data.source, "textures of the effect, in all");
            if (stored != data.format) data = texture::convert(data, stored);  // no copy when nothing changes
            add_texture(resource.name, std::move(data), resource.srgb);
        } catch (const effect::EffectError&) {
            throw;
        } catch (const std::exception& error) {
            bool overridden = values.textures.count(resource.name) > 0;  // the user's own file: its problem is reported
            for (const auto& p : effect.parameters)
                overridden = overridden || (effect::is_sampler_type(p.type) && p.texture == resource.name && values.textures.count(p.name));
            if (effect.legacy && !overridden && !dynamic_cast<const BudgetError*>(&error)) {
                add_placeholder(resource, error.what());
                continue;
            }
            throw effect::EffectError(resource.where, "texture " + resource.name + ": " + error.what());
        }
    }
    render_target_sizes(1, 1);  // fixed Dimensions are checked at load (`check`); ratios at each frame size
}

std::vector<glm::ivec2> EffectResources::render_target_sizes(int frame_width, int frame_height) const {
    std::vector<glm::ivec2> sizes;
    std::int64_t total = file_texture_bytes_;
    for (const auto& resource : effect_.textures) {
        if (!resource.render_target) continue;
        const double width = resource.dimensions ? resource.dimensions->x : std::max(1.0, std::round(frame_width * static_cast<double>(resource.viewport_ratio.x)));
        const double height = resource.dimensions ? resource.dimensions->y : std::max(1.0, std::round(frame_height * static_cast<double>(resource.viewport_ratio.y)));
        const texture::PixelFormat format = storage_format(resource.storage, texture::PixelFormat::RGBA32F);
        const double bytes = width * height * (format == texture::PixelFormat::RGBA8 ? 4 : format == texture::PixelFormat::RGBA16F ? 8 : 16);
        try {
            check_limit(effect_.limits, "texture-dimension", static_cast<std::int64_t>(std::min(std::max(width, height), 1e15)),
                        "render target " + resource.name, "side");
            check_limit(effect_.limits, "texture-bytes", static_cast<std::int64_t>(std::min(bytes, 1e15)), "render target " + resource.name, "size");
            total += static_cast<std::int64_t>(bytes);
            check_limit(effect_.limits, "effect-texture-bytes", total, "render target " + resource.name,
                        "textures and render targets of the effect, in all");
        } catch (const Error& error) {
            throw effect::EffectError(resource.where, error.what());
        }
        sizes.emplace_back(static_cast<int>(width), static_cast<int>(height));
    }
    return sizes;
}

void EffectResources::fit_render_targets(int frame_width, int frame_height) {
    const std::vector<glm::ivec2> sizes = render_target_sizes(frame_width, frame_height);
    size_t index = 0;
    for (const auto& resource : effect_.textures) {
        if (!resource.render_target) continue;
        const glm::ivec2 size = sizes[index++];
        const auto found = textures_.find(resource.name);
        if (found != textures_.end() && found->second.width == size.x && found->second.height == size.y) continue;
        GpuTexture gpu;
        gpu.format = storage_format(resource.storage, texture::PixelFormat::RGBA32F);
        if (texture::is_compressed(gpu.format)) gpu.format = texture::PixelFormat::RGBA32F;
        const GLenum internal = gpu.format == texture::PixelFormat::RGBA8     ? GL_RGBA8
                                : gpu.format == texture::PixelFormat::RGBA16F ? GL_RGBA16F
                                                                               : GL_RGBA32F;
        gpu.texture = gl::create_texture(GL_TEXTURE_2D);
        glTextureStorage2D(gpu.texture.get(), 1, internal, size.x, size.y);
        gpu.width = size.x;
        gpu.height = size.y;
        gpu.source = "render target";
        textures_.insert_or_assign(resource.name, std::move(gpu));
    }
}

const GpuTexture* EffectResources::find(const std::string& texture_name) const {
    if (const auto environment = environment_resources_.find(texture_name); environment != environment_resources_.end())
        return environment_ ? environment_->texture(environment->second) : nullptr;
    const auto found = textures_.find(texture_name);
    return found == textures_.end() ? nullptr : &found->second;
}

GLuint EffectResources::sampler(const effect::SamplerState& state) {
    const std::vector<GLenum> key = {state.min_filter, state.mag_filter, state.wrap_s, state.wrap_t, state.wrap_r};
    auto found = samplers_.find(key);
    if (found == samplers_.end()) {
        gl::Sampler sampler = gl::create_sampler();
        glSamplerParameteri(sampler.get(), GL_TEXTURE_MIN_FILTER, static_cast<GLint>(state.min_filter));
        glSamplerParameteri(sampler.get(), GL_TEXTURE_MAG_FILTER, static_cast<GLint>(state.mag_filter));
        glSamplerParameteri(sampler.get(), GL_TEXTURE_WRAP_S, static_cast<GLint>(state.wrap_s));
        glSamplerParameteri(sampler.get(), GL_TEXTURE_WRAP_T, static_cast<GLint>(state.wrap_t));
        glSamplerParameteri(sampler.get(), GL_TEXTURE_WRAP_R, static_cast<GLint>(state.wrap_r));
        found = samplers_.emplace(key, std::move(sampler)).first;
    }
    return found->second.get();
}

}  // namespace fxview::render
