// The scene environment on the GPU: the textures effects sample for image-based lighting, made
// from lighting/ on the CPU and kept there too for the CPU references (docs/effect-format.md,
// "Environment lighting"):
//   environment:specular    cube map, RGBA32F, one mip level per roughness step (level 0 the radiance; made on first use),
//                           without the disc lights (they are shaded in closed form)
//   environment:irradiance  17x1 RGBA32F: the order-2 SH coefficients of the cosine-convolved radiance / pi
//                           (without the discs), then per disc light (at most kMaxDiscs; the sun, a lamp)
//                           two texels: direction and angular radius, radiance x solid angle and solid
//                           angle (zero for no disc)
//   environment:dfg         2D RGBA32F: (A, B, G) of the split sum per (n·v, roughness), clamped at the edges
//   environment:spectral-weights  cube map, RGBA32F, one level: the weights of the environment's
//                           spectral form (lighting::SpectralForm, the built-in sky's), discs drawn in
//   environment:spectral-irradiance  cube map, RGBA32F, 32², one level: those weights cosine-convolved / π
//                           (lighting/cosine_convolution.hpp); made on first use
//   environment:spectral-lobe-weights  cube map, RGBA32F: the weights without the disc lights, level 0
//                           at kSize, each further level the mean of four texels (filtered sampling)
//   environment:lobe-mass   64x64 RGBA32F, laid out as the DFG table: the mass of the Phong and Blinn
//                           lobes above the surface per (n·v, log2(power) / 8), in units of 2 / (p + 1)
//                           (lighting/lobe_mass.hpp);
//                           made on first use
//   environment:spectral-discs  8x1 RGBA32F: per disc light (at most kMaxDiscs) its direction and
//                           angular radius, its weights and solid angle (zero where there is none)
//   environment:spectra     471x1 RGBA32F: its three spectra at 360-830 nm; alpha 1 where the
//                           environment has a spectral form, all 0 where it has none
//   environment:fourier     the thin-film sensitivity transforms of those three spectra under both
//                           observers, laid out as spectral:fourier (spectral/fourier_table.hpp):
//                           table observer · 3 + k; made on first use (a tenth of a second)
// No source: black textures of one texel (an effect samples them and adds nothing).
#pragma once
#include <memory>
#include <mutex>
#include <string>

#include "lighting/image_based_lighting.hpp"
#include "render/effect_resources.hpp"
#include "spectral/packing.hpp"
#include "texture/texture_data.hpp"

namespace fxview::render {

class EnvironmentMaps {
public:
    static constexpr int kSize = 256;    // texels across a face of the radiance (level 0)
    static constexpr int kLevels = 7;    // roughness (k/6)²: 0, 0.03, 0.11, 0.25, 0.44, 0.69, 1 on levels 256 .. 4
    static constexpr int kDfgSize = 64;
    static constexpr int kMaxDiscs = 4;  // as many as lighting::BrightSourceRules takes out of an image

    // Throws fxview::Error naming the source when it cannot be made.
    explicit EnvironmentMaps(const std::string& source, const ResourceLimits& limits = {});

    const std::string& source() const { return source_; }
    bool empty() const { return source_.empty(); }
    // The texture an "environment:..." ResourceName names; nullptr for an unknown name.
    const GpuTexture* texture(const std::string& resource_name) const;
    static bool is_resource_name(const std::string& name);
    static bool is_spectral_resource_name(const std::string& name);  // the spectral form's and the lobe-mass table (read only with it)
    bool has_spectral_form() const { return environment_.spectral.has_value(); }
    const texture::TextureData& spectral_weights_data() const { return spectral_weights_data_; }  // faces[face][0]
    // environment:spectral-lobe-weights: its number of levels and one level's six faces.
    int spectral_lobe_levels() const { return static_cast<int>(spectral_lobe_levels_.size()); }
    const texture::TextureData& spectral_lobe_level(int level) const { return spectral_lobe_levels_.at(static_cast<size_t>(level)); }
    // environment:spectral-irradiance on the CPU (made on first use, thread-safe); one level, or one
    // zero texel without a spectral form.
    const texture::TextureData& spectral_irradiance_data() const;
    // environment:fourier on the CPU (made on first use, thread-safe); nullptr without a spectral form.
    const spectral::PackedTexture* spectral_fourier() const;

    // The same numbers on the CPU.
    const lighting::PrefilteredEnvironment& prefiltered() const { return prefiltered_; }  // the SH and discs; `specular` empty
    const lighting::Environment& unfiltered() const { return environment_; }  // the radiance and its discs, for ground truths
    const lighting::DfgTable& dfg() const { return dfg_; }
    const lighting::DfgTable& lobe_mass() const;  // lighting::lobe_mass_table(), shared by every environment
    // environment:specular on the CPU, made on first use (thread-safe; seconds: the GGX prefiltering).
    const texture::TextureData& specular_data() const;          // faces[face][level], GL rows
    const texture::TextureData& specular_level(int level) const;  // one level's six faces
    // The radiance with the disc lights drawn in, one level: what the background shows.
    const GpuTexture& background() const { return background_; }

private:
    void make_specular() const;

    std::string source_, label_;  // label_: the source as texture names show it
    lighting::Environment environment_;
    lighting::PrefilteredEnvironment prefiltered_;
    lighting::DfgTable dfg_;
    mutable std::once_flag specular_made_;
    mutable texture::TextureData specular_data_;
    mutable std::vector<texture::TextureData> specular_levels_;
    mutable std::unique_ptr<GpuTexture> specular_;
    texture::TextureData spectral_weights_data_;
    std::vector<texture::TextureData> spectral_lobe_levels_;
    GpuTexture spectral_lobe_weights_, spectral_discs_;
    mutable std::once_flag spectral_irradiance_made_;
    mutable texture::TextureData spectral_irradiance_data_;
    mutable std::unique_ptr<GpuTexture> spectral_irradiance_;
    mutable std::unique_ptr<GpuTexture> lobe_mass_texture_;
    GpuTexture irradiance_, dfg_texture_, background_, spectral_weights_, spectra_;
    // The sky's Fourier tables: the CPU copy for references (any thread), the GL texture for the
    // render thread, each made when first asked for.
    mutable std::once_flag fourier_made_;
    mutable std::unique_ptr<spectral::PackedTexture> fourier_data_;
    mutable std::unique_ptr<GpuTexture> fourier_;
};

}  // namespace fxview::render
