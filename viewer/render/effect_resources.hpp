// The GPU resources of one loaded effect: its file textures (loaded, converted and uploaded once),
// its render targets (sized from the frame, recreated when the frame size changes) and sampler
// objects. Texture files are searched next to the effect, then in the texture folders.
// ResourceName "spectral:cmf" and "spectral:library" are generated: the CIE colour matching
// functions (colord-data) and the packed spectra of spectra/library.txt ($FXVIEW_SPECTRA_DIR);
// "spectral:fourier" the thin-film sensitivity transforms of those spectra (spectral/fourier_table.hpp).
#pragma once
#include <cstdint>
#include <map>
#include <mutex>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "effect/effect.hpp"
#include "effect/parameter_values.hpp"
#include "gl/objects.hpp"
#include "spectral/packing.hpp"
#include "texture/texture_data.hpp"

namespace fxview::render {

struct GpuTexture {
    gl::Texture texture;
    texture::TextureType type = texture::TextureType::Tex2D;
    texture::PixelFormat format = texture::PixelFormat::RGBA8;
    int width = 0, height = 0, levels = 1;  // levels as stored in GL, generated ones included
    bool generated_levels = false;          // the file had one level; GL made the others
    std::string source;  // file(s), or "render target"
};

class EnvironmentMaps;

class EffectResources {
public:
    // Throws EffectError at the texture's declaration for a missing, unreadable or unfit file.
    EffectResources(const effect::Effect& effect, const effect::ParameterValues& values,
                    const std::vector<std::string>& texture_dirs);

    // Makes every render target match the frame size (times its ViewportRatio, or its Dimensions).
    void fit_render_targets(int frame_width, int frame_height);
    const GpuTexture* find(const std::string& texture_name) const;  // nullptr for a generated one not yet acquired
    // The scene environment that "environment:..." textures come from (render/environment_maps.hpp);
    // set by the session before each frame.
    void set_environment(const EnvironmentMaps* environment) { environment_ = environment; }
    const EnvironmentMaps* environment() const { return environment_; }
    bool uses_environment() const { return !environment_resources_.empty(); }
    // find(), generating a generated texture on first use.
    const GpuTexture* acquire(const std::string& texture_name);
    GLuint sampler(const effect::SamplerState& state);
    const std::map<std::string, GpuTexture>& textures() const { return textures_; }
    const effect::Effect& effect() const { return effect_; }
    // CPU copies of generated textures ("spectral:cmf", "spectral:library", "spectral:fourier"), for
    // CPU references (made on first use; thread-safe); nullptr for other names.
    const spectral::PackedTexture* generated(const std::string& texture_name) const;
    // The same by resource name ("spectral:library"): whichever of the effect's textures it names.
    const spectral::PackedTexture* generated_resource(const std::string& resource) const;
    // CPU copies of file textures exactly as uploaded (after format conversion), for CPU references.
    const texture::TextureData* cpu_copy(const std::string& texture_name) const;
    // Legacy effects: textures replaced by placeholders, each "file:line: warning: ...".
    const std::vector<std::string>& warnings() const { return warnings_; }

private:
    void add_placeholder(const effect::TextureResource& resource, const std::string& problem);
    void add_texture(const std::string& name, texture::TextureData data, bool srgb);  // uploads it, keeps the CPU copy
    std::vector<std::string> warnings_;
    // Each render target's size for a frame, checked (with the file textures) against the effect's
    // budgets before anything is allocated; EffectError at the target's declaration.
    std::vector<glm::ivec2> render_target_sizes(int frame_width, int frame_height) const;

    std::int64_t file_texture_bytes_ = 0;  // what the effect's file textures store
    const effect::Effect& effect_;
    std::map<std::string, GpuTexture> textures_;
    std::map<std::string, const effect::TextureResource*> generated_resources_;
    std::map<std::string, std::string> environment_resources_;  // texture name -> "environment:..."
    const EnvironmentMaps* environment_ = nullptr;
    mutable std::mutex generated_mutex_;  // CPU references read generated textures from several threads
    mutable std::map<std::string, spectral::PackedTexture> generated_;  // made on first use
    std::map<std::string, texture::TextureData> cpu_copies_;
    std::map<std::vector<GLenum>, gl::Sampler> samplers_;
};

// spectra/library.txt of the source tree (or $FXVIEW_SPECTRA_DIR): the library `spectral:` textures use.
std::string spectral_library_path();

// The same for legacy effects, whose names are often Windows paths of another machine: with '/' for
// '\\', else the file name alone next to the effect or in the folders.
std::string resolve_legacy_texture_path(const std::string& file, const std::string& effect_path,
                                        const std::vector<std::string>& texture_dirs);

// The file a texture name refers to: absolute, next to the effect, or in one of the folders.
std::string resolve_texture_path(const std::string& file, const std::string& effect_path,
                                 const std::vector<std::string>& texture_dirs);

}  // namespace fxview::render
