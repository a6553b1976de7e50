#include "optics/grating.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace fxview::optics {

double grating_intensity(double x, int tracks) {
    const double a = std::numbers::pi * x;
    const double denominator = tracks * std::sin(a);
    if (std::abs(denominator) < 1e-12) return 1.0;  // at an order: the limit of the quotient
    const double ratio = std::sin(tracks * a) / denominator;
    return ratio * ratio;
}

double grating_intensity_phasors(double x, int tracks) {
    // Each phasor is the previous one turned by 2πx (a rounding per step: ~N·1e-16), in plain doubles:
    // std::complex's product checks for infinities and is several times slower.
    const double angle = 2.0 * std::numbers::pi * (x - std::floor(x)), turn_re = std::cos(angle), turn_im = std::sin(angle);
    double sum_re = 0, sum_im = 0, re = 1, im = 0;
    for (int k = 0; k < tracks; ++k) {
        sum_re += re;
        sum_im += im;
        const double next_re = re * turn_re - im * turn_im;
        im = re * turn_im + im * turn_re;
        re = next_re;
    }
    return (sum_re * sum_re + sum_im * sum_im) / (static_cast<double>(tracks) * tracks);
}

namespace {

constexpr double kPi = std::numbers::pi;

double sinc(double z) {
    const double a = kPi * z;
    return std::abs(a) < 1e-8 ? 1.0 - a * a / 6.0 : std::sin(a) / a;
}

// 8-point Gauss-Legendre nodes and weights on [-1, 1] (Abramowitz & Stegun table 25.4).
constexpr std::array<double, 4> kNodes = {0.183434642495649805, 0.525532409916328986, 0.796666477413626740, 0.960289856497536232};
constexpr std::array<double, 4> kWeights = {0.362683783378361983, 0.313706645877887287, 0.222381034453374471, 0.101228536290376259};

// ∫ f over [from, to], split into equal pieces of at most `piece`.
template <typename F>
double integrate(const F& f, double from, double to, double piece) {
    const int pieces = std::max(1, static_cast<int>(std::ceil((to - from) / piece)));
    const double h = (to - from) / pieces;
    double sum = 0;
    for (int p = 0; p < pieces; ++p) {
        const double centre = from + (p + 0.5) * h;
        for (size_t i = 0; i < kNodes.size(); ++i)
            sum += kWeights[i] * (f(centre - 0.5 * h * kNodes[i]) + f(centre + 0.5 * h * kNodes[i]));
    }
    return sum * 0.5 * h;
}

// ∫₀ᶻ sinc²(s) ds.
double sinc_squared_integral(double z) {
    if (z == 0) return 0;
    const double s = std::sin(kPi * z);
    return (sine_integral(2.0 * kPi * z) - s * s / (kPi * z)) / kPi;
}

}  // namespace

double tracks_box_average(double x, double width, int tracks) {
    if (tracks <= 1) return 1.0;
    // cos(2πkx) by turning a phasor (plain doubles; one rounding per step).
    const double angle = 2.0 * kPi * (x - std::floor(x)), turn_re = std::cos(angle), turn_im = std::sin(angle);
    double sum = tracks, re = turn_re, im = turn_im;
    for (int k = 1; k < tracks; ++k) {
        sum += 2.0 * (tracks - k) * re * sinc(k * width);
        const double next_re = re * turn_re - im * turn_im;
        im = re * turn_im + im * turn_re;
        re = next_re;
    }
    return sum / (static_cast<double>(tracks) * tracks);
}

double patch_box_average(double y, double width, int tracks) {
    const double z = tracks * y, w = tracks * width;
    // Below a hundredth of a fringe the difference of the two integrals cancels; Simpson's rule is
    // exact there to w^4 max|f (4th derivative)| / 2880 < 4e-12.
    if (w < 1e-2) {
        const double a = sinc(z - 0.5 * w), b = sinc(z), c = sinc(z + 0.5 * w);
        return (a * a + 4.0 * b * b + c * c) / 6.0;
    }
    return (sinc_squared_integral(z + 0.5 * w) - sinc_squared_integral(z - 0.5 * w)) / w;
}

double tracks_box_average_quadrature(double x, double width, int tracks) {
    if (width <= 0) return grating_intensity_phasors(x, tracks);
    const double whole = std::floor(width), from = x - 0.5 * width + whole, to = x + 0.5 * width;
    // The point intensity from the phasors' geometric series, sin(Nπx)/(N sin πx) squared (tested
    // against the explicit phasor sum): the explicit sum at every node would cost N times as much.
    const auto intensity = [tracks](double s) { return grating_intensity(s, tracks); };
    const double rest = to > from ? integrate(intensity, from, to, 0.5 / tracks) : 0.0;
    return (whole / tracks + rest) / width;
}

double patch_box_average_quadrature(double y, double width, int tracks) {
    const double z = tracks * y, w = tracks * width;
    const auto intensity = [](double s) {
        const double a = sinc(s);  // the amplitude of a uniformly lit segment: ∫ exp(2πi s u) du over u in [-1/2, 1/2]
        return a * a;
    };
    if (w <= 0) return intensity(z);
    // Half a fringe per piece, but at most 8192 pieces: past that the box is thousands of fringes wide
    // and its far fringes, below 1e-7, are integrated more coarsely.
    return integrate(intensity, z - 0.5 * w, z + 0.5 * w, std::max(0.5, w / 8192.0)) / w;
}

double sine_integral(double t) {
    if (t < 0) return -sine_integral(-t);
    if (t <= 4.0) {
        // Σ (−1)^k t^(2k+1) / ((2k+1)(2k+1)!): 20 terms leave < 1e-20 at t = 4.
        double term = t, sum = t;
        for (int k = 1; k < 20; ++k) {
            term *= -t * t / ((2.0 * k) * (2.0 * k + 1.0));
            sum += term / (2.0 * k + 1.0);
        }
        return sum;
    }
    // Si(t) = π/2 + Im E₁(it), E₁(z) = e^(−z) / (z + 1 − 1²/(z + 3 − 2²/(z + 5 − ...))) from the tail.
    constexpr int kTerms = 30;
    // In plain doubles: std::complex's division guards against infinities and is slow.
    double f_re = 2.0 * kTerms + 1.0, f_im = t;
    for (int i = kTerms; i >= 1; --i) {
        const double scale = static_cast<double>(i) * i / (f_re * f_re + f_im * f_im);  // i² / f = i² conj(f) / |f|²
        f_re = 2.0 * i - 1.0 - scale * f_re;
        f_im = t + scale * f_im;
    }
    // Im(e^(−it) / f) = Im((cos t − i sin t) conj(f)) / |f|²
    return kPi / 2.0 + (-std::sin(t) * f_re - std::cos(t) * f_im) / (f_re * f_re + f_im * f_im);
}

namespace thesis {

CdIntensity cd_intensity(double spacing_nm, double influence, double cos_view, double cos_light, double wavelength_nm,
                         double threshold) {
    CdIntensity result{};
    result.spacing_nm = spacing_nm * (1.0 + 2.0 * influence);
    result.cycles = result.spacing_nm * std::abs(cos_view - cos_light) / wavelength_nm;
    const double fraction = result.cycles - std::floor(result.cycles);
    result.intensity = fraction > threshold ? fraction : 0.0;
    return result;
}

}  // namespace thesis
}  // namespace fxview::optics
