// Colorimetry against numbers nobody here wrote: CIE chromaticities of the standard illuminants,
// the Planckian locus, the sRGB white point; file round trips and the packed textures.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <fstream>

#include "core/error.hpp"
#include "spectral/colorimetry.hpp"
#include "spectral/generators.hpp"
#include "spectral/level_of_detail.hpp"
#include "spectral/library.hpp"
#include "spectral/packing.hpp"
#include "spectral/spectral_files.hpp"
#include "test_support.hpp"

using namespace fxview;
using namespace fxview::spectral;
using fxview::test::temp_path;

namespace {

const Observer& cie1931() {
    static const Observer o = load_observer("1931");
    return o;
}
const Observer& cie1964() {
    static const Observer o = load_observer("1964");
    return o;
}

std::array<double, 2> xy_of(const std::string& source, const Observer& observer) {
    return chromaticity(spectrum_to_xyz(spectrum_from_source(source, ".").spectrum, observer));
}

// The published chromaticities come from the CIE's own tables; ours integrate colord's 5 nm tables
// linearly resampled to 1 nm. The resampling moves x and y by a few 1e-5 (measured for every case
// below: at most 7.8e-5, Planck at 2856 K), and the published values are rounded to 4 decimals
// (+-5e-5): 1.5e-4 covers both.
constexpr double kXyTolerance = 1.5e-4;

}  // namespace

TEST_CASE("CIE 1931 chromaticities of D65, A and E") {
    const auto d65 = xy_of("colord:illuminant/CIE-D65.sp", cie1931());
    CHECK(std::abs(d65[0] - 0.3127) < kXyTolerance);
    CHECK(std::abs(d65[1] - 0.3290) < kXyTolerance);
    const auto a = xy_of("colord:illuminant/CIE-A.sp", cie1931());
    CHECK(std::abs(a[0] - 0.4476) < kXyTolerance);
    CHECK(std::abs(a[1] - 0.4074) < kXyTolerance);
    const auto e = xy_of("colord:illuminant/CIE-E.sp", cie1931());
    // E is constant: x = X/(X+Y+Z) depends only on the CMF sums, which the CIE makes equal (1/3).
    CHECK(std::abs(e[0] - 1.0 / 3.0) < kXyTolerance);
    CHECK(std::abs(e[1] - 1.0 / 3.0) < kXyTolerance);
    const auto d50 = xy_of("colord:illuminant/CIE-D50.sp", cie1931());
    CHECK(std::abs(d50[0] - 0.3457) < kXyTolerance);
    CHECK(std::abs(d50[1] - 0.3585) < kXyTolerance);
}

TEST_CASE("CIE 1964 chromaticity of D65") {
    const auto d65 = xy_of("colord:illuminant/CIE-D65.sp", cie1964());
    CHECK(std::abs(d65[0] - 0.3138) < kXyTolerance);
    CHECK(std::abs(d65[1] - 0.3310) < kXyTolerance);
}

TEST_CASE("k normalisation: a constant spectrum of 1 gives Y = 1 for every range and step") {
    for (const Integration range : {Integration{360, 830, 1}, Integration{400, 700, 5}, Integration{450, 650, 10}}) {
        const Vec3 xyz = spectrum_to_xyz(Spectrum::constant(1.0), cie1931(), range);
        CHECK(xyz[1] == doctest::Approx(1.0).epsilon(1e-12));
    }
    CHECK_THROWS_AS(spectrum_to_xyz(Spectrum::constant(1.0), cie1931(), {500, 400, 1}), UsageError);
}

TEST_CASE("generators: daylight reproduces D65 and D50, Planck follows the Planckian locus") {
    const auto xy = [](const Spectrum& s) { return chromaticity(spectrum_to_xyz(s, cie1931())); };
    // D65 is daylight at 6504 K, D50 at 5003 K (CIE 15: the nominal CCTs times 1.4388/1.4380).
    const auto d65 = xy(cie_daylight(6504));
    CHECK(std::abs(d65[0] - 0.3127) < kXyTolerance);
    CHECK(std::abs(d65[1] - 0.3290) < kXyTolerance);
    const auto d50 = xy(cie_daylight(5003));
    CHECK(std::abs(d50[0] - 0.3457) < kXyTolerance);
    CHECK(std::abs(d50[1] - 0.3585) < kXyTolerance);
    // Planckian locus (CIE 1931, c2 = 1.4388e-2 m K): 2856 K (illuminant A) at (0.4476, 0.4074).
    const auto a = xy(blackbody(2856));
    CHECK(std::abs(a[0] - 0.4476) < kXyTolerance);
    CHECK(std::abs(a[1] - 0.4074) < kXyTolerance);
    CHECK(blackbody(5000)[560] == doctest::Approx(1.0));
    CHECK_THROWS_AS(cie_daylight(3000), UsageError);
    CHECK(gaussian(550, 10)[550] == 1.0);
    CHECK(gaussian(550, 10)[560] == doctest::Approx(std::exp(-0.5)));
    CHECK(box(500, 510)[505] == 1.0);
    CHECK(box(500, 510)[511] == 0.0);
    CHECK(ramp(400, 500)[450] == doctest::Approx(0.5));
}

TEST_CASE("XYZ to sRGB (eq. 9): the D65 white maps to equal channels; gamut handling") {
    Vec3 white = spectrum_to_xyz(spectrum_from_source("colord:illuminant/CIE-D65.sp", ".").spectrum, cie1931());
    const Vec3 rgb = xyz_to_linear_srgb_unclipped(white);
    // Eq. 9 is built for the D65 white (0.3127, 0.3290): channels agree to the xy tolerance.
    CHECK(std::abs(rgb[0] - rgb[1]) < 2e-3);
    CHECK(std::abs(rgb[2] - rgb[1]) < 2e-3);
    // A spectral green far outside the gamut: clip keeps hue roughly, desaturate removes negatives
    // by mixing with grey, scale keeps ratios.
    const Vec3 green = spectrum_to_xyz(gaussian(520, 5), cie1931());
    const Vec3 raw = xyz_to_linear_srgb_unclipped(green);
    CHECK(raw[0] < 0);
    const Vec3 desaturated = xyz_to_linear_srgb(green, GamutMapping::Desaturate);
    CHECK(desaturated[0] >= 0);
    CHECK(desaturated[1] > desaturated[0]);
    const Vec3 scaled = xyz_to_linear_srgb(Vec3{green[0] * 10, green[1] * 10, green[2] * 10}, GamutMapping::Scale);
    CHECK(std::max({scaled[0], scaled[1], scaled[2]}) == doctest::Approx(1.0));
    CHECK(srgb_encode(0.5) == doctest::Approx(0.735356983));
}

TEST_CASE("CSV and CGATS files: read, write, read back; errors name file and line") {
    const Spectrum g = gaussian(600, 40);
    const std::string csv = temp_path("g.csv");
    write_csv(csv, g, 380, 780, 5);
    const NamedSpectrum back = read_csv(csv, Extrapolation::Hold);
    CHECK(back.spectrum[600] == doctest::Approx(1.0));
    // Linear interpolation between 5 nm samples of a Gaussian of sigma 40: error < h^2/8 * max|f''|
    // = 25/8 / 1600 = 2e-3.
    CHECK(std::abs(back.spectrum[602] - g[602]) < 2e-3);
    const std::string cgats = temp_path("two.sp");
    write_cgats(cgats, {{"first", g, ""}, {"second", box(500, 600), ""}}, 380, 780, 10);
    const auto sets = read_cgats(cgats, Extrapolation::Zero);
    REQUIRE(sets.size() == 2);
    CHECK(sets[1].name == "second");
    CHECK(sets[1].spectrum[550] == 1.0);
    CHECK(sets[1].spectrum[300] == 0.0);  // Zero outside the data
    const std::string bad = temp_path("bad.csv");
    std::ofstream(bad) << "nm,value\n400,0.1\n410,oops\n";
    CHECK_THROWS_WITH_AS(read_csv(bad, Extrapolation::Hold), doctest::Contains("bad.csv:3: expected 'nm,value'"), Error);
    std::ofstream(bad) << "400,0.1\n390,0.2\n";
    CHECK_THROWS_WITH_AS(read_csv(bad, Extrapolation::Hold), doctest::Contains("bad.csv:2: wavelengths must increase"), Error);
    const std::string short_cgats = temp_path("short.sp");
    std::ofstream(short_cgats) << "SPECT\nBEGIN_DATA_FORMAT\nSPEC_400 SPEC_410\nEND_DATA_FORMAT\nBEGIN_DATA\n0.1\nEND_DATA\n";
    CHECK_THROWS_WITH_AS(read_cgats(short_cgats, Extrapolation::Zero), doctest::Contains("short.sp:6: data set has 1 values"), Error);
}

TEST_CASE("the spectral library: every entry loads, indices are stable, emission peaks are 1") {
    const SpectralLibrary library = load_library(FXVIEW_SOURCE_SPECTRA_DIR "/library.txt");
    CHECK(library.index_of("E") == 0);
    CHECK(library.index_of("D65") == 5);
    CHECK(library.at("TCS01").kind == "reflectance");
    CHECK(library.entries.size() >= 24);
    double peak = 0;
    for (int nm = 360; nm <= 830; ++nm) peak = std::max(peak, library.at("F11").named.spectrum[nm]);
    CHECK(peak == doctest::Approx(1.0));
    CHECK_THROWS_WITH_AS(library.at("Gold"), doctest::Contains("no spectrum 'Gold'"), UsageError);
    const std::string bad = temp_path("library.txt");
    std::ofstream(bad) << "X = emission constant:1\nY = glowing box:1,2\n";
    CHECK_THROWS_WITH_AS(load_library(bad), doctest::Contains("library.txt:2: expected"), Error);
}

TEST_CASE("packed spectrum textures round-trip: float exact, 8-bit within half a code") {
    const SpectralLibrary library = load_library(FXVIEW_SOURCE_SPECTRA_DIR "/library.txt");
    const auto spectra = library.spectra();
    const PackedTexture full = pack_spectra(spectra, texture::PixelFormat::RGBA32F);
    CHECK(full.texture.width() == 1024);
    CHECK(full.texture.height() == static_cast<int>((spectra.size() + 7) / 8));
    const PackedTexture bytes = pack_spectra(spectra, texture::PixelFormat::RGBA8);
    for (size_t s = 0; s < spectra.size(); ++s)
        for (int nm = kCmfFirstNm; nm <= kCmfLastNm; nm += 7) {  // 8-bit clips beyond 830 nm
            const double want = spectra[s].spectrum.at(nm);
            CHECK(packed_value(full, static_cast<int>(s), nm) == doctest::Approx(want).epsilon(1e-7));  // float32 rounding
            // Rounding to the nearest of 256 codes, plus the float32 division code / 255 on reading (~6e-8).
            CHECK(std::abs(packed_value(bytes, static_cast<int>(s), nm) - want) <= 0.5 / 255.0 * bytes.scale + 1e-7);
        }
    const PackedTexture cmf = cmf_texture(cie1931(), cie1964(), texture::PixelFormat::RGBA32F);
    CHECK(cmf.texture.width() == 471);
    CHECK(cmf_value(cmf, 0, 555)[1] == doctest::Approx(cie1931().y[555]).epsilon(1e-7));
    CHECK(cmf_value(cmf, 1, 600)[0] == doctest::Approx(cie1964().x[600]).epsilon(1e-7));
    const PackedTexture cmf8 = cmf_texture(cie1931(), cie1964(), texture::PixelFormat::RGBA8);
    CHECK(cmf8.scale == doctest::Approx(std::max(cie1931().z.max(), cie1964().z.max())));  // the zbar peak
}

TEST_CASE("CIELAB: the white is L* = 100, sRGB red has its published coordinates") {
    const Vec3 d65_white{0.95047, 1.0, 1.08883};
    const Vec3 white = xyz_to_lab(d65_white, d65_white);
    CHECK(white[0] == doctest::Approx(100.0).epsilon(1e-12));
    CHECK(std::abs(white[1]) < 1e-12);
    CHECK(std::abs(white[2]) < 1e-12);
    // sRGB's red primary (XYZ 0.4124, 0.2126, 0.0193) is L*a*b* = (53.24, 80.09, 67.20) in every
    // sRGB reference (e.g. Lindbloom's calculator); 0.02 covers the 4-digit XYZ and 2-digit Lab.
    const Vec3 red = xyz_to_lab({0.4124, 0.2126, 0.0193}, d65_white);
    CHECK(red[0] == doctest::Approx(53.24).epsilon(0.02 / 53.24));
    CHECK(red[1] == doctest::Approx(80.09).epsilon(0.02 / 80.09));
    CHECK(red[2] == doctest::Approx(67.20).epsilon(0.02 / 67.20));
    CHECK(delta_e_ab({50, 3, 4}, {50, 0, 0}) == doctest::Approx(5.0).epsilon(1e-15));
}

TEST_CASE("level of detail: level 9 is the full sum, interpolation is exact at support points") {
    CHECK(lod_spacing(9) == 1);
    CHECK(lod_spacing(6) == 8);
    CHECK(lod_spacing(1) == 256);
    CHECK_THROWS_AS(lod_spacing(0), fxview::UsageError);
    const auto square = [](int nm) { return static_cast<double>(nm) * nm; };
    CHECK(lod_interpolated(square, 400, 360, 830, 8) == 400.0 * 400.0);                             // a support point
    CHECK(lod_interpolated(square, 372, 360, 830, 8) == doctest::Approx((368.0 * 368 + 376.0 * 376) / 2));  // midway
    CHECK(lod_interpolated(square, 829, 360, 830, 8) == doctest::Approx((824.0 * 824 * 1 + 830.0 * 830 * 5) / 6));  // last, short interval
    const SpectralLibrary library = load_library(FXVIEW_SOURCE_SPECTRA_DIR "/library.txt");
    const Spectrum tcs09 = library.spectra().at(static_cast<size_t>(library.index_of("TCS09"))).spectrum;
    const Vec3 full = spectrum_to_xyz(tcs09, cie1931());
    const Vec3 level9 = spectrum_to_xyz_lod(tcs09, cie1931(), 360, 830, 1);
    for (int c = 0; c < 3; ++c) CHECK(level9[c] == doctest::Approx(full[c]).epsilon(1e-12));
    // A constant spectrum stays Y = 1 at every level (k follows the interpolated ybar).
    for (int level = 1; level <= 9; ++level)
        CHECK(spectrum_to_xyz_lod(Spectrum::constant(1.0), cie1931(), 360, 830, lod_spacing(level))[1] == doctest::Approx(1.0).epsilon(1e-12));
}
