#include "render/environment_maps.hpp"

#include <cstring>

#include "core/error.hpp"
#include "gl/texture_upload.hpp"
#include "lighting/cosine_convolution.hpp"
#include "lighting/environment_sources.hpp"
#include "lighting/lobe_mass.hpp"
#include "spectral/colorimetry.hpp"
#include "spectral/fourier_table.hpp"

namespace fxview::render {
namespace {

texture::Level float_level(int width, int height, const std::vector<float>& rgba) {
    texture::Level level;
    level.width = width;
    level.height = height;
    level.bytes.resize(rgba.size() * sizeof(float));
    std::memcpy(level.bytes.data(), rgba.data(), level.bytes.size());
    return level;
}

texture::Level cube_face_level(const lighting::FloatCube& cube, int face) {
    std::vector<float> rgba;
    rgba.reserve(static_cast<size_t>(cube.size) * cube.size * 4);
    for (const glm::vec3& c : cube.faces[static_cast<size_t>(face)]) rgba.insert(rgba.end(), {c.r, c.g, c.b, 1.0f});
    return float_level(cube.size, cube.size, rgba);
}

GpuTexture upload(const texture::TextureData& data, const std::string& source) {
    GpuTexture gpu;
    gpu.texture = gl::upload_texture(data, {false, false});
    gpu.type = data.type;
    gpu.format = data.format;
    gpu.width = data.width();
    gpu.height = data.height();
    gpu.levels = data.levels();
    gpu.source = source;
    return gpu;
}

// A table of (n·v, second coordinate) as a 2D texture: rows top first in TextureData, the table's
// row j is GL row j from the bottom.
texture::TextureData table_data(const lighting::DfgTable& t, const std::string& source) {
    std::vector<float> rgba;
    for (int j = t.size - 1; j >= 0; --j)
        for (int i = 0; i < t.size; ++i) {
            const glm::vec3 value = t.data[static_cast<size_t>(j) * t.size + i];
            rgba.insert(rgba.end(), {value.x, value.y, value.z, 1.0f});
        }
    return {texture::TextureType::Tex2D, texture::PixelFormat::RGBA32F, {{float_level(t.size, t.size, rgba)}}, source};
}

}  // namespace

bool EnvironmentMaps::is_resource_name(const std::string& name) {
    return name == "environment:specular" || name == "environment:irradiance" || name == "environment:dfg" || name == "environment:lobe-mass" ||
           is_spectral_resource_name(name);
}

bool EnvironmentMaps::is_spectral_resource_name(const std::string& name) {
    // lobe-mass: only the spectral lobes read it (environment_spectral_lobes.glsl).
    return name == "environment:spectral-weights" || name == "environment:spectral-irradiance" || name == "environment:spectral-lobe-weights" ||
           name == "environment:spectral-discs" || name == "environment:spectra" || name == "environment:fourier" || name == "environment:lobe-mass";
}

EnvironmentMaps::EnvironmentMaps(const std::string& source, const ResourceLimits& limits) : source_(source) {
    label_ = source.empty() ? "no environment" : source;
    if (source.empty()) {
        environment_.radiance = lighting::FloatCube(1);
        prefiltered_.irradiance.fill(glm::vec3(0.0f));
        dfg_.size = 1;
        dfg_.data.assign(1, glm::vec3(0.0f));
    } else {
        environment_ = lighting::make_environment(source, kSize, limits);
        prefiltered_ = lighting::prefilter_irradiance(environment_);  // the specular levels when first asked for
        dfg_ = lighting::make_dfg_table(kDfgSize);
    }

    std::vector<float> sh;
    for (const glm::vec3& c : prefiltered_.irradiance) sh.insert(sh.end(), {c.r, c.g, c.b, 1.0f});
    // Texels 9 + 2k and 10 + 2k: disc k as direction and angular radius, radiance x solid angle and
    // solid angle; zero where there is none.
    if (environment_.discs.size() > kMaxDiscs)
        throw Error(source + ": " + std::to_string(environment_.discs.size()) + " disc lights, more than the " + std::to_string(kMaxDiscs) +
                    " the GPU tables hold");
    for (int k = 0; k < kMaxDiscs; ++k) {
        if (static_cast<size_t>(k) < environment_.discs.size()) {
            const lighting::DiscLight& disc = environment_.discs[static_cast<size_t>(k)];
            const glm::dvec3 power = disc.radiance * disc.solid_angle();
            sh.insert(sh.end(), {static_cast<float>(disc.direction.x), static_cast<float>(disc.direction.y), static_cast<float>(disc.direction.z),
                                 static_cast<float>(disc.angular_radius), static_cast<float>(power.r), static_cast<float>(power.g),
                                 static_cast<float>(power.b), static_cast<float>(disc.solid_angle())});
        } else {
            sh.insert(sh.end(), 8, 0.0f);
        }
    }
    texture::TextureData irradiance{texture::TextureType::Tex2D, texture::PixelFormat::RGBA32F, {{float_level(9 + 2 * kMaxDiscs, 1, sh)}},
                                    label_ + " (SH irradiance, disc lights)"};
    irradiance_ = upload(irradiance, irradiance.source);

    texture::TextureData background{texture::TextureType::Cube, texture::PixelFormat::RGBA32F, {}, label_ + " (background)"};
    const lighting::FloatCube with_discs = environment_.radiance_with_discs();
    for (int face = 0; face < 6; ++face) background.faces.push_back({cube_face_level(with_discs, face)});
    background_ = upload(background, background.source);

    const texture::TextureData dfg = table_data(dfg_, "split-sum DFG table");
    dfg_texture_ = upload(dfg, dfg.source);

    // The spectral form: its weights as a cube of one level, its spectra as a row of 471 texels (RGB the
    // three spectra, alpha 1 where the environment has the form; all zero where it has none).
    spectral_weights_data_ = texture::TextureData{texture::TextureType::Cube, texture::PixelFormat::RGBA32F, {}, label_ + " (spectral weights)"};
    const lighting::FloatCube no_weights(1);
    for (int face = 0; face < 6; ++face)
        spectral_weights_data_.faces.push_back({cube_face_level(environment_.spectral ? environment_.spectral->weights : no_weights, face)});
    // For lobes: the weights without the discs in box-filtered levels down to one texel, the discs apart.
    texture::TextureData lobe_weights{texture::TextureType::Cube, texture::PixelFormat::RGBA32F, {}, label_ + " (spectral weights without discs)"};
    lobe_weights.faces.resize(6);
    std::vector<lighting::FloatCube> chain{environment_.spectral ? environment_.spectral->map_weights : no_weights};
    while (chain.back().size > 1) chain.push_back(lighting::downsample(chain.back()));
    for (const lighting::FloatCube& level : chain) {
        texture::TextureData one{texture::TextureType::Cube, texture::PixelFormat::RGBA32F, {}, lobe_weights.source};
        for (int face = 0; face < 6; ++face) {
            lobe_weights.faces[static_cast<size_t>(face)].push_back(cube_face_level(level, face));
            one.faces.push_back({cube_face_level(level, face)});
        }
        spectral_lobe_levels_.push_back(std::move(one));
    }
    spectral_lobe_weights_ = upload(lobe_weights, lobe_weights.source);
    std::vector<float> discs;
    const std::vector<lighting::DiscLight> no_discs;
    const std::vector<lighting::DiscLight>& spectral_discs = environment_.spectral ? environment_.spectral->discs : no_discs;
    if (spectral_discs.size() > kMaxDiscs) throw Error(source + ": more disc lights than the " + std::to_string(kMaxDiscs) + " the GPU tables hold");
    for (size_t k = 0; k < kMaxDiscs; ++k) {
        if (k >= spectral_discs.size()) {
            discs.insert(discs.end(), 8, 0.0f);
            continue;
        }
        const lighting::DiscLight& disc = spectral_discs[k];
        discs.insert(discs.end(), {static_cast<float>(disc.direction.x), static_cast<float>(disc.direction.y), static_cast<float>(disc.direction.z),
                                   static_cast<float>(disc.angular_radius), static_cast<float>(disc.radiance.r), static_cast<float>(disc.radiance.g),
                                   static_cast<float>(disc.radiance.b), static_cast<float>(disc.solid_angle())});
    }
    const texture::TextureData disc_table{texture::TextureType::Tex2D, texture::PixelFormat::RGBA32F, {{float_level(2 * kMaxDiscs, 1, discs)}},
                                          label_ + " (spectral disc lights)"};
    spectral_discs_ = upload(disc_table, disc_table.source);
    spectral_weights_ = upload(spectral_weights_data_, spectral_weights_data_.source);
    std::vector<float> spectra;
    for (int nm = lighting::SpectralForm::kFirstNm; nm <= lighting::SpectralForm::kLastNm; ++nm) {
        const size_t i = static_cast<size_t>(nm - lighting::SpectralForm::kFirstNm);
        for (int k = 0; k < 3; ++k) spectra.push_back(environment_.spectral ? static_cast<float>(environment_.spectral->spectra[static_cast<size_t>(k)][i]) : 0.0f);
        spectra.push_back(environment_.spectral ? 1.0f : 0.0f);
    }
    const int count = lighting::SpectralForm::kLastNm - lighting::SpectralForm::kFirstNm + 1;
    texture::TextureData row{texture::TextureType::Tex2D, texture::PixelFormat::RGBA32F, {{float_level(count, 1, spectra)}}, label_ + " (spectra)"};
    spectra_ = upload(row, row.source);
}

const GpuTexture* EnvironmentMaps::texture(const std::string& name) const {
    if (name == "environment:specular") {
        if (!specular_) specular_ = std::make_unique<GpuTexture>(upload(specular_data(), label_ + " (prefiltered)"));
        return specular_.get();
    }
    if (name == "environment:irradiance") return &irradiance_;
    if (name == "environment:dfg") return &dfg_texture_;
    if (name == "environment:lobe-mass") {
        if (!lobe_mass_texture_) lobe_mass_texture_ = std::make_unique<GpuTexture>(upload(table_data(lobe_mass(), "lobe mass table"), "lobe mass table"));
        return lobe_mass_texture_.get();
    }
    if (name == "environment:spectral-weights") return &spectral_weights_;
    if (name == "environment:spectra") return &spectra_;
    if (name == "environment:spectral-lobe-weights") return &spectral_lobe_weights_;
    if (name == "environment:spectral-discs") return &spectral_discs_;
    if (name == "environment:spectral-irradiance") {
        if (!spectral_irradiance_) spectral_irradiance_ = std::make_unique<GpuTexture>(upload(spectral_irradiance_data(), spectral_irradiance_data().source));
        return spectral_irradiance_.get();
    }
    if (name == "environment:fourier") {
        if (!fourier_) {
            // Without a spectral form: one zero texel, as the other textures (nothing samples it then).
            const spectral::PackedTexture* table = spectral_fourier();
            const texture::TextureData none{texture::TextureType::Tex2D, texture::PixelFormat::RGBA32F, {{float_level(1, 1, {0, 0, 0, 0})}},
                                            "no spectral environment"};
            fourier_ = std::make_unique<GpuTexture>(upload(table ? table->texture : none, label_ + " (thin-film transforms)"));
        }
        return fourier_.get();
    }
    return nullptr;
}

void EnvironmentMaps::make_specular() const {
    std::call_once(specular_made_, [this] {
        const std::vector<lighting::FloatCube> levels =
            source_.empty() ? std::vector<lighting::FloatCube>{lighting::FloatCube(1)} : lighting::prefilter_specular(environment_, kLevels);
        specular_data_ = texture::TextureData{texture::TextureType::Cube, texture::PixelFormat::RGBA32F, {}, label_};
        specular_data_.faces.resize(6);
        for (int face = 0; face < 6; ++face)
            for (const auto& level : levels) specular_data_.faces[static_cast<size_t>(face)].push_back(cube_face_level(level, face));
        for (size_t level = 0; level < levels.size(); ++level) {
            texture::TextureData one{texture::TextureType::Cube, texture::PixelFormat::RGBA32F, {}, label_};
            for (const auto& face : specular_data_.faces) one.faces.push_back({face[level]});
            specular_levels_.push_back(std::move(one));
        }
    });
}

const texture::TextureData& EnvironmentMaps::specular_data() const {
    make_specular();
    return specular_data_;
}

const texture::TextureData& EnvironmentMaps::specular_level(int level) const {
    make_specular();
    return specular_levels_.at(static_cast<size_t>(level));
}

const lighting::DfgTable& EnvironmentMaps::lobe_mass() const { return lighting::lobe_mass_table(); }

const texture::TextureData& EnvironmentMaps::spectral_irradiance_data() const {
    std::call_once(spectral_irradiance_made_, [this] {
        spectral_irradiance_data_ = texture::TextureData{texture::TextureType::Cube, texture::PixelFormat::RGBA32F, {},
                                                         label_ + " (spectral weights, cosine-convolved)"};
        const lighting::FloatCube cube = environment_.spectral ? lighting::cosine_convolved(environment_.spectral->weights) : lighting::FloatCube(1);
        for (int face = 0; face < 6; ++face) spectral_irradiance_data_.faces.push_back({cube_face_level(cube, face)});
    });
    return spectral_irradiance_data_;
}

const spectral::PackedTexture* EnvironmentMaps::spectral_fourier() const {
    if (!environment_.spectral) return nullptr;
    std::call_once(fourier_made_, [this] {
        std::vector<spectral::NamedSpectrum> spectra(3);
        for (size_t k = 0; k < 3; ++k) {
            spectra[k].name = "environment spectrum " + std::to_string(k);
            // As the GPU's environment:spectra holds them (float), zero outside 360-830 nm.
            for (int nm = lighting::SpectralForm::kFirstNm; nm <= lighting::SpectralForm::kLastNm; ++nm)
                spectra[k].spectrum[nm] = static_cast<float>(environment_.spectral->spectra[k][static_cast<size_t>(nm - lighting::SpectralForm::kFirstNm)]);
        }
        fourier_data_ = std::make_unique<spectral::PackedTexture>(
            spectral::fourier_table(spectra, spectral::load_observer("1931"), spectral::load_observer("1964")));
    });
    return fourier_data_.get();
}

}  // namespace fxview::render
