#include "spectral/fourier_table.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numbers>

#include "core/error.hpp"
#include "core/parallel.hpp"

namespace fxview::spectral {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

void store(texture::Level& level, int x, int stored_row, const Vec3& value) {
    const size_t texel = static_cast<size_t>(stored_row) * static_cast<size_t>(level.width) + static_cast<size_t>(x);
    for (size_t c = 0; c < 3; ++c) {
        const float f = static_cast<float>(value[c]);
        std::memcpy(&level.bytes[texel * 16 + c * 4], &f, 4);
    }
}

// One table: the envelope G_c(D_k) for k = 0 .. kFourierSamples − 1, by rotating each wavelength's
// phasor one step at a time (exact to ~1e-13 after 4096 steps in double).
void fill_table(texture::Level& level, int first_gl_row, const Observer& observer, const Spectrum& light) {
    double ybar_sum = 0;
    for (int nm = kCmfFirstNm; nm <= kCmfLastNm; ++nm) ybar_sum += observer.y.at(nm);
    struct Sample { double w[3]; double step_re, step_im; double re = 1, im = 0; };
    std::vector<Sample> samples;
    Vec3 weight_sum{}, frequency_sum{};
    for (int nm = kCmfFirstNm; nm <= kCmfLastNm; ++nm) {
        const double l = light.at(nm) / ybar_sum;
        Sample s{{observer.x.at(nm) * l, observer.y.at(nm) * l, observer.z.at(nm) * l},
                 std::cos(kTwoPi * kFourierStepNm / nm), std::sin(kTwoPi * kFourierStepNm / nm)};
        for (size_t c = 0; c < 3; ++c) {
            weight_sum[c] += s.w[c];
            frequency_sum[c] += s.w[c] / nm;
        }
        samples.push_back(s);
    }
    Vec3 centre{};
    // Rounded to float as stored, so that the shader's carrier undoes exactly this demodulation.
    for (size_t c = 0; c < 3; ++c) centre[c] = static_cast<float>(weight_sum[c] > 0 ? frequency_sum[c] / weight_sum[c] : 1.0 / 550.0);
    const int height = level.height;
    std::vector<Vec3> magnitude(kFourierSamples);
    for (int k = 0; k < kFourierSamples; ++k) {
        double re[3] = {0, 0, 0}, im[3] = {0, 0, 0};
        for (Sample& s : samples) {
            for (int c = 0; c < 3; ++c) {
                re[c] += s.w[c] * s.re;
                im[c] += s.w[c] * s.im;
            }
            const double next_re = s.re * s.step_re - s.im * s.step_im;
            s.im = s.re * s.step_im + s.im * s.step_re;
            s.re = next_re;
        }
        Vec3 envelope_re{}, envelope_im{};
        for (size_t c = 0; c < 3; ++c) {
            // Cycles reduced to [0, 1) before the angle is formed: D ν reaches ~90.
            const double cycles = k * kFourierStepNm * centre[c];
            const double angle = -kTwoPi * (cycles - std::floor(cycles));
            const double cr = std::cos(angle), ci = std::sin(angle);
            envelope_re[c] = re[c] * cr - im[c] * ci;
            envelope_im[c] = re[c] * ci + im[c] * cr;
        }
        // Magnitudes of the values as stored (float), which bound what interpolation between them gives.
        for (size_t c = 0; c < 3; ++c)
            magnitude[static_cast<size_t>(k)][c] = std::hypot(static_cast<double>(static_cast<float>(envelope_re[c])),
                                                             static_cast<double>(static_cast<float>(envelope_im[c])));
        store(level, k, height - 1 - first_gl_row, envelope_re);
        store(level, k, height - 2 - first_gl_row, envelope_im);
    }
    store(level, 0, height - 3 - first_gl_row, centre);
    // Past the table: a bound on |F| (= |G|, the envelope) up to kFourierBeyondNm, continuing the
    // phasors from where the table ends with samples every h = 2 kFourierStepNm. Between samples, with
    // G(D) = Σ w e^{i2πD(1/λ − ν)}: |G(D)| <= |G(s)| + |G'(s)| h/2 + max|G''| h²/8, where
    // G' = Σ w i2π(1/λ − ν) e^{...} is summed alongside and |G''| <= (2πB)² F(0), B = max |1/λ − ν|.
    Vec3 tail{}, spread{}, white{};
    for (const Sample& s : samples)
        for (size_t c = 0; c < 3; ++c) white[c] += s.w[c];
    for (int nm = kCmfFirstNm; nm <= kCmfLastNm; ++nm)
        for (size_t c = 0; c < 3; ++c) spread[c] = std::max(spread[c], std::abs(1.0 / nm - centre[c]));
    constexpr double h = 2 * kFourierStepNm;
    for (Sample& s : samples) {  // one step of h: two of the table's
        const double r = s.step_re * s.step_re - s.step_im * s.step_im;
        s.step_im = 2 * s.step_re * s.step_im;
        s.step_re = r;
    }
    const int beyond = static_cast<int>((kFourierBeyondNm - kFourierStepNm * kFourierSamples) / h);
    for (int k = 0; k <= beyond; ++k) {
        double re[3] = {0, 0, 0}, im[3] = {0, 0, 0}, slope_re[3] = {0, 0, 0}, slope_im[3] = {0, 0, 0};
        int index = 0;
        for (Sample& s : samples) {
            const double frequency = 1.0 / (kCmfFirstNm + index++);
            for (int c = 0; c < 3; ++c) {
                re[c] += s.w[c] * s.re;
                im[c] += s.w[c] * s.im;
                slope_re[c] += s.w[c] * (frequency - centre[static_cast<size_t>(c)]) * s.re;
                slope_im[c] += s.w[c] * (frequency - centre[static_cast<size_t>(c)]) * s.im;
            }
            const double next_re = s.re * s.step_re - s.im * s.step_im;
            s.im = s.re * s.step_im + s.im * s.step_re;
            s.re = next_re;
        }
        for (size_t c = 0; c < 3; ++c) {
            const double curvature = std::pow(kTwoPi * spread[c], 2) * white[c];
            tail[c] = std::max(tail[c], std::hypot(re[c], im[c]) + kTwoPi * std::hypot(slope_re[c], slope_im[c]) * h / 2 + curvature * h * h / 8);
        }
    }
    // Row 3t + 2, texel k >= 1: the largest |F| from sample k on (a running maximum from the end, the
    // part past the table included), rounded up to float so that it stays a bound.
    for (int k = kFourierSamples - 1; k >= 1; --k) {
        for (size_t c = 0; c < 3; ++c) tail[c] = std::max(tail[c], magnitude[static_cast<size_t>(k)][c]);
        Vec3 stored{};
        for (size_t c = 0; c < 3; ++c) stored[c] = std::nextafter(static_cast<float>(tail[c]), 1.0f);
        store(level, k, height - 3 - first_gl_row, stored);
    }
}

Vec3 read(const PackedTexture& table, int x, int gl_row) {
    float rgba[4];
    texture::read_texel(table.texture, 0, 0, x, table.texture.height() - 1 - gl_row, rgba);
    return {rgba[0], rgba[1], rgba[2]};
}

}  // namespace

PackedTexture fourier_table(const std::vector<NamedSpectrum>& spectra, const Observer& cie1931, const Observer& cie1964) {
    if (spectra.empty()) throw Error("fourier table: the spectral library is empty");
    const int tables = 2 * static_cast<int>(spectra.size());
    PackedTexture packed;
    packed.texture.format = texture::PixelFormat::RGBA32F;
    packed.texture.source = "thin-film sensitivity transforms";
    const int height = tables * kFourierRowsPerTable;
    packed.texture.faces = {{texture::Level{kFourierSamples, height,
                                            std::vector<std::uint8_t>(texture::level_size(texture::PixelFormat::RGBA32F, kFourierSamples, height))}}};
    texture::Level& level = packed.texture.faces[0][0];
    // Tables are independent: one per task, on all cores (~50 ms each on one core).
    parallel_sum<int>(static_cast<size_t>(tables), [&](size_t begin, size_t end) {
        for (size_t t = begin; t < end; ++t) {
            const Observer& observer = t < spectra.size() ? cie1931 : cie1964;
            fill_table(level, static_cast<int>(t) * kFourierRowsPerTable, observer, spectra[t % spectra.size()].spectrum);
        }
        return 0;
    }, 2);
    return packed;
}

namespace {

int table_row(const PackedTexture& table, int observer_row, int spectrum) {
    const int spectra = table.texture.height() / (2 * kFourierRowsPerTable);
    return (observer_row * spectra + spectrum) * kFourierRowsPerTable;
}

}  // namespace

double fourier_tail_bound(const PackedTexture& table, int observer_row, int spectrum, double path_difference_nm) {
    const double x = path_difference_nm / kFourierStepNm;
    const int row = table_row(table, observer_row, spectrum);
    // Texel 0 of that row holds the centres; from sample 0 on the largest |F| is F(0) itself; past
    // the table, the last texel: the largest |F| sampled beyond it.
    const int i = static_cast<int>(std::min(x, static_cast<double>(kFourierSamples - 1)));
    const Vec3 tail = i == 0 ? read(table, 0, row) : read(table, i, row + 2);
    return std::max({tail[0], tail[1], tail[2]});
}

ComplexXyz fourier_lookup(const PackedTexture& table, int observer_row, int spectrum, double path_difference_nm, double path_spread_nm) {
    const int row = table_row(table, observer_row, spectrum);
    const double x = path_difference_nm / kFourierStepNm;
    ComplexXyz f{};
    if (!(x >= 0) || x >= kFourierSamples - 1) return f;  // the incoherent limit (see the header)
    const int i = static_cast<int>(x);
    const double t = x - i;
    const Vec3 re0 = read(table, i, row), re1 = read(table, i + 1, row);
    const Vec3 im0 = read(table, i, row + 1), im1 = read(table, i + 1, row + 1);
    const Vec3 centre = read(table, 0, row + 2);
    // The spread's second difference about sample j (the header), read once for the three channels.
    Vec3 curve_re{}, curve_im{};
    if (path_spread_nm > 0.0) {
        const int j = std::max(i, 1);
        const Vec3 a_re = read(table, j - 1, row), b_re = read(table, j, row), c_re = read(table, j + 1, row);
        const Vec3 a_im = read(table, j - 1, row + 1), b_im = read(table, j, row + 1), c_im = read(table, j + 1, row + 1);
        for (size_t c = 0; c < 3; ++c) {
            curve_re[c] = c_re[c] - 2.0 * b_re[c] + a_re[c];
            curve_im[c] = c_im[c] - 2.0 * b_im[c] + a_im[c];
        }
    }
    for (size_t c = 0; c < 3; ++c) {
        std::complex<double> envelope((1 - t) * re0[c] + t * re1[c], (1 - t) * im0[c] + t * im1[c]);
        const double phase_spread = kTwoPi * centre[c] * path_spread_nm;
        if (path_spread_nm > 0.0) {  // the first- and second-order terms of the spread (the header)
            const double tilt = kTwoPi * path_spread_nm * path_spread_nm * centre[c] / kFourierStepNm;
            const double bend = 0.5 * path_spread_nm * path_spread_nm * (1.0 - phase_spread * phase_spread) / (kFourierStepNm * kFourierStepNm);
            envelope += std::complex<double>(bend * curve_re[c] - tilt * (im1[c] - im0[c]), bend * curve_im[c] + tilt * (re1[c] - re0[c]));
        }
        const double cycles = path_difference_nm * centre[c];
        f[c] = envelope * std::polar(std::exp(-0.5 * phase_spread * phase_spread), kTwoPi * (cycles - std::floor(cycles)));
    }
    return f;
}

}  // namespace fxview::spectral
