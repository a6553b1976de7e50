// Spectra and colour matching functions as textures (seed 002 fig. 19, Code 4/9/10; the thesis'
// SpectralLibrarian and CIEXYZ2Texture).
//   Packed spectra: 512 samples for 324..835 nm, four consecutive wavelengths per RGBA texel, so
//   128 texels per spectrum; spectrum s starts at texel 128*(s % per_row) of row s / per_row.
//   CMF texture: one texel per nm from 360 to 830 (R = xbar, G = ybar, B = zbar, A = 1); row 0 is
//   the CIE 1931 2 degree observer, row 1 the CIE 1964 10 degree observer.
// 8-bit storage divides by a scale (the largest value within 360-830 nm) and rounds; the scale is returned so that a
// shader can multiply it back. Float storage uses scale 1.
#pragma once
#include <vector>

#include "spectral/colorimetry.hpp"
#include "texture/texture_data.hpp"

namespace fxview::spectral {

constexpr int kPackedFirstNm = 324;
constexpr int kPackedSamples = 512;
constexpr int kTexelsPerSpectrum = kPackedSamples / 4;
constexpr int kSpectraPerRow = 8;
constexpr int kCmfFirstNm = 360;
constexpr int kCmfLastNm = 830;

struct PackedTexture {
    texture::TextureData texture;
    double scale = 1.0;  // stored value * scale = spectral value
    int count = 0;       // spectra packed (pack_spectra)
};

PackedTexture pack_spectra(const std::vector<NamedSpectrum>& spectra, texture::PixelFormat format);
// The value a shader fetches for spectrum `index` at `nm` (324..835), undoing the scale. Error for an
// index that is not one of the packed spectra (a parameter value must never read beyond the table).
double packed_value(const PackedTexture& packed, int index, int nm);

PackedTexture cmf_texture(const Observer& cie1931, const Observer& cie1964, texture::PixelFormat format);
// xbar, ybar, zbar as stored in row `observer_row` at `nm` (360..830), undoing the scale.
Vec3 cmf_value(const PackedTexture& cmf, int observer_row, int nm);

}  // namespace fxview::spectral
