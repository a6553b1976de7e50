#include "spectral/packing.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include <glm/gtc/packing.hpp>

#include "core/error.hpp"

namespace fxview::spectral {
namespace {

using texture::PixelFormat;

// Writes one float into channel c of texel i of a level, in the level's format.
void store(texture::Level& level, PixelFormat format, size_t texel, int channel, double value) {
    switch (format) {
        case PixelFormat::RGBA8:
            level.bytes[texel * 4 + channel] = static_cast<std::uint8_t>(std::lround(std::clamp(value, 0.0, 1.0) * 255.0));
            break;
        case PixelFormat::RGBA16F: {
            const std::uint16_t half = glm::packHalf1x16(static_cast<float>(value));
            std::memcpy(&level.bytes[texel * 8 + channel * 2], &half, 2);
            break;
        }
        case PixelFormat::RGBA32F: {
            const float f = static_cast<float>(value);
            std::memcpy(&level.bytes[texel * 16 + channel * 4], &f, 4);
            break;
        }
        default: throw Error("spectral textures are stored as RGBA8, RGBA16F or RGBA32F");
    }
}

PackedTexture make(int width, int height, PixelFormat format) {
    PackedTexture packed;
    packed.texture.format = format;
    packed.texture.faces = {{texture::Level{width, height, std::vector<std::uint8_t>(texture::level_size(format, width, height))}}};
    return packed;
}

}  // namespace

PackedTexture pack_spectra(const std::vector<NamedSpectrum>& spectra, PixelFormat format) {
    if (spectra.empty()) throw Error("no spectra to pack");
    const int rows = (static_cast<int>(spectra.size()) + kSpectraPerRow - 1) / kSpectraPerRow;
    PackedTexture packed = make(kSpectraPerRow * kTexelsPerSpectrum, rows, format);
    packed.texture.source = "packed spectra";
    packed.count = static_cast<int>(spectra.size());
    if (format == PixelFormat::RGBA8) {
        // Scaled by the largest value inside the CMF range 360-830 nm (1 for the normalised library);
        // the few samples beyond 830 nm that the packing also holds are clipped to it.
        double peak = 0;
        for (const auto& s : spectra)
            for (int nm = kCmfFirstNm; nm <= kCmfLastNm; ++nm) peak = std::max(peak, s.spectrum.at(nm));
        packed.scale = peak > 0 ? peak : 1.0;
    }
    texture::Level& level = packed.texture.faces[0][0];
    for (size_t s = 0; s < spectra.size(); ++s) {
        // Texture rows are stored top row first; row r of the texture (GL t from the bottom) is
        // uploaded flipped, so spectra go bottom-up here to land in GL row s / kSpectraPerRow.
        const int gl_row = static_cast<int>(s) / kSpectraPerRow;
        const int stored_row = rows - 1 - gl_row;
        const int first_texel = kTexelsPerSpectrum * (static_cast<int>(s) % kSpectraPerRow);
        for (int i = 0; i < kPackedSamples; ++i) {
            const size_t texel = static_cast<size_t>(stored_row) * level.width + first_texel + i / 4;
            store(level, format, texel, i % 4, spectra[s].spectrum.at(kPackedFirstNm + i) / packed.scale);
        }
    }
    return packed;
}

double packed_value(const PackedTexture& packed, int index, int nm) {
    if (index < 0 || index >= packed.count)
        throw Error("spectrum index " + std::to_string(index) + " is not in the library (0.." + std::to_string(packed.count - 1) + ")");
    const int i = nm - kPackedFirstNm;
    if (i < 0 || i >= kPackedSamples) return 0.0;
    const int rows = packed.texture.height();
    const int stored_row = rows - 1 - index / kSpectraPerRow;
    const int x = kTexelsPerSpectrum * (index % kSpectraPerRow) + i / 4;
    float rgba[4];
    texture::read_texel(packed.texture, 0, 0, x, stored_row, rgba);
    return static_cast<double>(rgba[i % 4]) * packed.scale;
}

PackedTexture cmf_texture(const Observer& cie1931, const Observer& cie1964, PixelFormat format) {
    const int width = kCmfLastNm - kCmfFirstNm + 1;
    PackedTexture packed = make(width, 2, format);
    packed.texture.source = "CIE colour matching functions";
    if (format == PixelFormat::RGBA8) {
        // Global scaling by the largest value (the zbar peak, as in seed 002 ch. 4.2).
        double peak = 0;
        for (const Observer* o : {&cie1931, &cie1964})
            for (int nm = kCmfFirstNm; nm <= kCmfLastNm; ++nm) peak = std::max({peak, o->x[nm], o->y[nm], o->z[nm]});
        packed.scale = peak;
    }
    texture::Level& level = packed.texture.faces[0][0];
    const Observer* observers[2] = {&cie1931, &cie1964};
    for (int row = 0; row < 2; ++row) {
        const int stored_row = 1 - row;  // GL row 0 is the last stored row
        for (int nm = kCmfFirstNm; nm <= kCmfLastNm; ++nm) {
            const size_t texel = static_cast<size_t>(stored_row) * width + (nm - kCmfFirstNm);
            store(level, format, texel, 0, observers[row]->x[nm] / packed.scale);
            store(level, format, texel, 1, observers[row]->y[nm] / packed.scale);
            store(level, format, texel, 2, observers[row]->z[nm] / packed.scale);
            store(level, format, texel, 3, 1.0);
        }
    }
    return packed;
}

Vec3 cmf_value(const PackedTexture& cmf, int observer_row, int nm) {
    if (nm < kCmfFirstNm || nm > kCmfLastNm) return {0, 0, 0};
    float rgba[4];
    texture::read_texel(cmf.texture, 0, 0, nm - kCmfFirstNm, 1 - observer_row, rgba);
    return {rgba[0] * cmf.scale, rgba[1] * cmf.scale, rgba[2] * cmf.scale};
}

}  // namespace fxview::spectral
