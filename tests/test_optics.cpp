// Thin-film optics against textbook closed forms that nobody here derived: normal-incidence and
// Brewster reflectance, total internal reflection, the metal formula, quarter-wave AR coatings and
// Bragg mirrors (Hecht, Optics, ch. 4 and 9; Macleod, Thin-Film Optical Filters, ch. 2-4), energy
// conservation, and two independent exact methods (Airy's sum, characteristic matrices) agreeing.
// Every tolerance here is about double rounding (1e-12) unless a comment says otherwise.
#include <doctest/doctest.h>

#include <cmath>
#include <algorithm>
#include <numbers>
#include <vector>

#include "core/error.hpp"
#include "optics/film_series.hpp"
#include "optics/grating.hpp"
#include "optics/grating_orders.hpp"
#include "optics/prepared_stack.hpp"
#include "optics/thesis_models.hpp"
#include "optics/thin_film.hpp"

using namespace fxview::optics;

namespace {

constexpr double kExact = 1e-12;  // a handful of double operations on values of order 1

double degrees_to_cos(double degrees) { return std::cos(degrees * std::numbers::pi / 180.0); }

Stack single_film(double n0, double n1, double n2, double d) { return Stack{n0, {Layer{n1, d}}, n2}; }

}  // namespace

TEST_CASE("a bare interface: normal incidence, Brewster's angle, total internal reflection") {
    // Hecht eq. 4.67: R = ((n - 1)/(n + 1))² = 0.04 for glass of n = 1.5.
    CHECK(interface_reflectance(1.0, 1.5, 1.0) == doctest::Approx(0.04).epsilon(kExact));
    CHECK(transfer_matrix_reflectance(Stack{1.0, {}, 1.5}, 550.0, 1.0) == doctest::Approx(0.04).epsilon(kExact));

    // At Brewster's angle tan θB = n the parallel reflectance vanishes and R⊥ = ((n² − 1)/(n² + 1))².
    const double cos_brewster = std::cos(std::atan(1.5));
    const Complex cos_t = refracted_cos(1.0, 1.5, cos_brewster);
    CHECK(std::norm(fresnel(1.0, 1.5, cos_brewster, cos_t, Polarisation::P).r) < 1e-28);
    CHECK(std::norm(fresnel(1.0, 1.5, cos_brewster, cos_t, Polarisation::S).r) ==
          doctest::Approx(std::pow(1.25 / 3.25, 2)).epsilon(kExact));

    // Glass to air beyond the critical angle (41.8°): everything is reflected, in both polarisations.
    const double cos60 = degrees_to_cos(60.0);
    for (const Polarisation p : {Polarisation::S, Polarisation::P})
        CHECK(transfer_matrix(Stack{1.5, {}, 1.0}, 550.0, cos60, p).reflectance == doctest::Approx(1.0).epsilon(kExact));
}

TEST_CASE("a metal at normal incidence: R = ((n − 1)² + κ²) / ((n + 1)² + κ²)") {
    for (const auto& [n, kappa] : {std::pair{0.2, 3.0}, std::pair{0.47, 2.4}, std::pair{1.5, 0.0}}) {
        const double expected = ((n - 1) * (n - 1) + kappa * kappa) / ((n + 1) * (n + 1) + kappa * kappa);
        CHECK(interface_reflectance(1.0, Complex(n, kappa), 1.0) == doctest::Approx(expected).epsilon(kExact));
        CHECK(transfer_matrix_reflectance(Stack{1.0, {}, Complex(n, kappa)}, 600.0, 1.0) ==
              doctest::Approx(expected).epsilon(kExact));
    }
}

TEST_CASE("quarter- and half-wave layers at their design wavelength") {
    const double lambda0 = 550.0, glass = 1.52;
    // Quarter-wave layer: R = ((n0 ns − n1²)/(n0 ns + n1²))²; MgF2 (1.38) on crown glass gives the
    // textbook 1.26 % (Hecht 9.9), and n1 = √ns makes a perfect anti-reflection coating.
    const double mgf2 = 1.38;
    const double expected = std::pow((glass - mgf2 * mgf2) / (glass + mgf2 * mgf2), 2);
    CHECK(expected == doctest::Approx(0.0126).epsilon(0.01));  // the 1.26 % as printed (3 digits)
    CHECK(transfer_matrix_reflectance(single_film(1.0, mgf2, glass, lambda0 / (4 * mgf2)), lambda0, 1.0) ==
          doctest::Approx(expected).epsilon(kExact));
    CHECK(transfer_matrix_reflectance(single_film(1.0, std::sqrt(glass), glass, lambda0 / (4 * std::sqrt(glass))), lambda0, 1.0) <
          1e-24);
    // A half-wave layer is "absent" (Macleod 2.4): the bare substrate's reflectance, for any n1.
    for (const double n1 : {1.38, 2.3})
        CHECK(transfer_matrix_reflectance(single_film(1.0, n1, glass, lambda0 / (2 * n1)), lambda0, 1.0) ==
              doctest::Approx(interface_reflectance(1.0, glass, 1.0)).epsilon(kExact));
}

TEST_CASE("a quarter-wave Bragg mirror (HL)^N H reaches the closed-form peak reflectance") {
    // Macleod 5.2 / Hecht eq. 9.107: with an H layer on top of N (HL) pairs, Y = (nH/nL)^(2N) nH²/ns
    // and R = ((n0 − Y)/(n0 + Y))² at λ0.
    const double lambda0 = 600.0, n_high = 2.35, n_low = 1.38, substrate = 1.52;
    for (const int pairs : {1, 3, 7}) {
        Stack stack{1.0, {}, substrate};
        for (int i = 0; i < pairs; ++i) {
            stack.layers.push_back({n_high, lambda0 / (4 * n_high)});
            stack.layers.push_back({n_low, lambda0 / (4 * n_low)});
        }
        stack.layers.push_back({n_high, lambda0 / (4 * n_high)});
        const double y = std::pow(n_high / n_low, 2 * pairs) * n_high * n_high / substrate;
        CAPTURE(pairs);
        CHECK(transfer_matrix_reflectance(stack, lambda0, 1.0) == doctest::Approx(std::pow((1 - y) / (1 + y), 2)).epsilon(1e-11));
    }
}

TEST_CASE("lossless stacks conserve energy, at any angle and polarisation") {
    Stack stack{1.0, {{2.1, 137.0}, {1.46, 212.0}, {1.9, 55.0}}, 1.52};
    for (const double degrees : {0.0, 30.0, 65.0, 85.0})
        for (const Polarisation p : {Polarisation::S, Polarisation::P})
            for (const double lambda : {380.0, 512.0, 777.0}) {
                const Response r = transfer_matrix(stack, lambda, degrees_to_cos(degrees), p);
                CHECK(r.reflectance + r.transmittance == doctest::Approx(1.0).epsilon(kExact));
            }
}

TEST_CASE("a thick absorbing layer reflects like the bulk material (the sign of κ is the decaying one)") {
    // Gold-like n̂ = 0.3 + 2.9i: the field decays as exp(−4πκd/λ) = 1e-40 after 2 µm at 550 nm.
    const Complex metal(0.3, 2.9);
    const Stack thick{1.0, {{metal, 2000.0}}, 1.52};
    for (const double degrees : {0.0, 45.0, 80.0})
        CHECK(transfer_matrix_reflectance(thick, 550.0, degrees_to_cos(degrees)) ==
              doctest::Approx(interface_reflectance(1.0, metal, degrees_to_cos(degrees))).epsilon(kExact));
}

TEST_CASE("Airy's sum (eq. 47) and the characteristic matrices agree for one film") {
    for (const double degrees : {0.0, 25.0, 60.0, 80.0})
        for (const double d : {0.0, 90.0, 333.0, 1200.0})
            for (const double lambda : {380.0, 550.0, 830.0}) {
                const double cos0 = degrees_to_cos(degrees);
                for (const Polarisation p : {Polarisation::S, Polarisation::P})
                    CHECK(airy_reflectance(1.0, 1.33, 1.5, d, lambda, cos0, p) ==
                          doctest::Approx(transfer_matrix(single_film(1.0, 1.33, 1.5, d), lambda, cos0, p).reflectance)
                              .epsilon(kExact));
                // A film of higher index than the substrate (the thesis' n = 1.0 / 2.0 / 1.5, fig. 26).
                CHECK(airy_reflectance(1.0, 2.0, 1.5, d, lambda, cos0) ==
                      doctest::Approx(transfer_matrix_reflectance(single_film(1.0, 2.0, 1.5, d), lambda, cos0)).epsilon(kExact));
            }
}

TEST_CASE("a soap film (Sun, eq. 48/49) is black when thin and matches a free film's matrices") {
    for (const double d : {0.0, 1.0, 150.0, 420.0})
        for (const double degrees : {0.0, 50.0}) {
            const double cos0 = degrees_to_cos(degrees);
            CHECK(bubble_reflectance(1.0, 1.33, d, 500.0, cos0) ==
                  doctest::Approx(transfer_matrix_reflectance(single_film(1.0, 1.33, 1.0, d), 500.0, cos0)).epsilon(kExact));
        }
    // The "black film" of a bursting bubble: for d → 0 reflectance vanishes like d² (here 1 nm: < 1e-3).
    CHECK(bubble_reflectance(1.0, 1.33, 0.0, 500.0, 1.0) == 0.0);
    CHECK(bubble_reflectance(1.0, 1.33, 1.0, 500.0, 1.0) < 1e-3);
}

TEST_CASE("the thesis' approximate models evaluate their documented formulas") {
    // Values of the printed formulas for n = 1.0 / 1.33 / 1.5 at normal incidence, worked out by hand
    // (python3) from eq. 62, Code 15, eq. 65 and eq. 66; 1e-9 covers the 10 digits kept.
    // Eq. 62: 2 · 136 nm · 2.0 · 1 · 1 / 500 nm = 1.088 cycles.
    const thesis::PathDifference path = thesis::path_difference(1.0, 2.0, 136.0, 500.0, 1.0, 1.0);
    CHECK(path.cycles == doctest::Approx(1.088).epsilon(kExact));
    CHECK(path.intensity == doctest::Approx(0.088).epsilon(1e-9));
    CHECK(thesis::durikovic(1.0, 1.33, 1.5, 0.0, 500.0, 1.0) == doctest::Approx(0.006766721994).epsilon(1e-9));
    CHECK(thesis::alternative(1.0, 1.33, 1.5, 0.0, 500.0, 1.0) == doctest::Approx(0.01991769948).epsilon(1e-9));
    CHECK(thesis::fabry_perot(1.0, 1.33, 100.0, 500.0, 1.0) == doctest::Approx(0.4321908952).epsilon(1e-9));
    // Eq. 65 truncates the beams and would reflect up to 1.18 of the light at n 2.5 / 3.0 / 1.0 (550 nm,
    // total reflection at the substrate, 87°, 82.5 nm: worked out in python3): clamped, it reaches
    // exactly 1 and never more.
    double most = 0;
    for (double c = 0.01; c <= 1.0; c += 0.01)
        for (double d = 0; d <= 200; d += 0.5) most = std::max(most, thesis::alternative(2.5, 3.0, 1.0, d, 550.0, c));
    CHECK(most == 1.0);

    // What the approximations cost: with no film at all the exact answer is the bare 1.0/1.5
    // interface (R = 0.04); Code 15 gives 0.0068 and eq. 65 0.0199 (DOMAIN.md §3).
    CHECK(airy_reflectance(1.0, 1.33, 1.5, 0.0, 500.0, 1.0) == doctest::Approx(0.04).epsilon(kExact));
    CHECK(std::abs(thesis::durikovic(1.0, 1.33, 1.5, 0.0, 500.0, 1.0) - 0.04) > 0.03);
    // Fabry-Pérot with the thesis' R: transmission is complete (nothing reflected) where Δ = 2πm,
    // as for the exact free film.
    const double full_wave = 500.0 / (2 * 1.33);
    CHECK(thesis::fabry_perot(1.0, 1.33, full_wave, 500.0, 1.0) < 1e-20);
    CHECK(bubble_reflectance(1.0, 1.33, full_wave, 500.0, 1.0) < 1e-20);
}

TEST_CASE("grazing incidence reflects everything") {
    // The limit θ0 → 90° of every Fresnel coefficient is −1; the matrices must not divide by cos θ0 = 0.
    const Stack stack{1.0, {{1.33, 300.0}, {2.0, 80.0}}, Complex(0.3, 2.9)};
    for (const Polarisation p : {Polarisation::S, Polarisation::P})
        CHECK(transfer_matrix(stack, 500.0, 0.0, p).reflectance == 1.0);
    CHECK(transfer_matrix_reflectance(stack, 500.0, 1e-7) == doctest::Approx(1.0).epsilon(1e-5));
}

TEST_CASE("equal indices do not bend light, even a hair from grazing") {
    // cos θt = cos θi exactly when n_t = n_i; the printed 1 - (1 - cos²) loses cos_i below 1e-8.
    for (const double cos_i : {1e-12, 1e-9, 1e-4, 0.5})
        CHECK(refracted_cos(Complex(1.33), Complex(1.33), Complex(cos_i)).real() == doctest::Approx(cos_i).epsilon(1e-12));
}

TEST_CASE("a CD's tracks: N-slit interference peaks where the grating equation says") {
    // Closed form against the explicit phasor sum (1e-12), for track counts from 2 to 50.
    for (const int tracks : {2, 7, 50})
        for (const double x : {0.0, 0.13, 0.5, 0.999, 1.0, 2.37, 3.0})
            CHECK(grating_intensity(x, tracks) == doctest::Approx(grating_intensity_phasors(x, tracks)).epsilon(1e-12).scale(1.0));
    // Orders at integer x (full intensity), zeros at x = m/N between them.
    CHECK(grating_intensity(2.0, 10) == 1.0);
    CHECK(grating_intensity(0.1, 10) < 1e-28);
    CHECK(grating_intensity(0.3, 10) < 1e-28);
    // Light along the normal, d = 1600 nm (CD): green 500 nm leaves in first order at
    // sin θ = λ/d = 0.3125 (18.2°, Hecht eq. 10.61), a DVD (740 nm) sends it to sin θ = 0.676 (42.5°).
    CHECK(grating_intensity(1600.0 * 0.3125 / 500.0, 20) == doctest::Approx(1.0).epsilon(1e-12));
    CHECK(grating_intensity(740.0 * (500.0 / 740.0) / 500.0, 20) == doctest::Approx(1.0).epsilon(1e-12));
    CHECK(grating_intensity(1600.0 * 0.29 / 500.0, 20) < 0.05);  // 1.3° off the order: dark (20 tracks)
}

TEST_CASE("the sine integral against Abramowitz & Stegun's table 5.1") {
    // Tabulated to 12 digits; the series (t <= 4) and the continued fraction (t > 4) hold 1e-12.
    const std::vector<std::pair<double, double>> table = {{0.5, 0.493107418043}, {1.0, 0.946083070367}, {2.0, 1.605412976803},
                                                          {4.0, 1.758203138949}, {5.0, 1.549931244945}, {10.0, 1.658347594219},
                                                          {20.0, 1.548241701043}};
    for (const auto& entry : table) {
        const double t = entry.first, si = entry.second;
        CAPTURE(t);
        CHECK(sine_integral(t) == doctest::Approx(si).epsilon(1e-12).scale(1.0));
        CHECK(sine_integral(-t) == -sine_integral(t));
    }
    CHECK(sine_integral(1e6) == doctest::Approx(std::numbers::pi / 2).epsilon(2e-6).scale(1.0));  // |Si − π/2| <= 1/t
}

TEST_CASE("a CD patch averaged over a pixel: closed forms against quadrature of the phasor sums") {
    // Two methods that share no formula (Fejér series and sine integral against Gauss-Legendre
    // quadrature of explicit phasors); both are accurate to ~1e-12, so 1e-9 can only fail on a defect.
    for (const int tracks : {1, 2, 7, 60, 200})
        for (const double x : {0.0, 0.004, 0.13, 0.5, 2.37, -3.01})
            for (const double width : {0.0, 1e-5, 3e-3, 0.02, 0.4, 1.0, 2.7}) {
                CAPTURE(tracks);
                CAPTURE(x);
                CAPTURE(width);
                CHECK(tracks_box_average(x, width, tracks) ==
                      doctest::Approx(tracks_box_average_quadrature(x, width, tracks)).epsilon(1e-9).scale(1.0));
                CHECK(patch_box_average(x, width, tracks) ==
                      doctest::Approx(patch_box_average_quadrature(x, width, tracks)).epsilon(1e-9).scale(1.0));
            }
    // Limits nobody needs a formula for: a point footprint is the point value; a footprint of whole
    // periods averages the N-track term to 1/N (Parseval); a footprint much wider than the patch's
    // fringe holds all of sinc²'s unit area; the zero order is a full-strength highlight.
    CHECK(tracks_box_average(0.13, 0.0, 7) == doctest::Approx(grating_intensity(0.13, 7)).epsilon(1e-12));
    CHECK(tracks_box_average(0.37, 3.0, 7) == doctest::Approx(1.0 / 7).epsilon(1e-12));
    CHECK(patch_box_average(0.0, 100.0 / 60, 60) == doctest::Approx(1.0 / 100).epsilon(3e-3));  // tails beyond ±50 fringes: 2/(π² 50)/100
    CHECK(tracks_box_average(0.0, 0.0, 60) * patch_box_average(0.0, 0.0, 60) == doctest::Approx(1.0));
    // Off the zero order along the tracks, the first zero of the patch lies at N y = 1.
    CHECK(patch_box_average(1.0 / 60, 0.0, 60) < 1e-20);
}

TEST_CASE("the thesis' CD intensity (eq. 72) with its spacing rule and hard threshold") {
    // Light across the tracks: d_eff = d. 1600 · |0.9 − 0.6| / 400 = 1.2 cycles → 0.2, below 0.5 → cut.
    const auto cut = thesis::cd_intensity(1600.0, 0.0, 0.9, 0.6, 400.0, 0.5);
    CHECK(cut.cycles == doctest::Approx(1.2).epsilon(1e-12));
    CHECK(cut.intensity == 0.0);
    // Light along the tracks: d_eff = 3d = 4800; 4800 · 0.3 / 400 = 3.6 → 0.6, kept.
    const auto kept = thesis::cd_intensity(1600.0, 1.0, 0.9, 0.6, 400.0, 0.5);
    CHECK(kept.spacing_nm == 4800.0);
    CHECK(kept.intensity == doctest::Approx(0.6).epsilon(1e-9));
}

TEST_CASE("the film's cosine series (Belcour-Barla) sums to the transfer-matrix reflectance") {
    // At high order the truncation is below 1e-12 (|x|^60); the transfer matrix is independent code
    // (characteristic matrices), so agreement to 1e-10 checks the coefficients and the phase sign.
    struct Case {
        double n1;
        Complex n2;
        double cos0, thickness;
    };
    for (const Case& c : {Case{1.33, {1.0, 0.0}, 1.0, 300.0}, Case{1.33, {1.5, 0.0}, 0.6, 550.0}, Case{2.4, {1.5, 0.0}, 0.2, 120.0},
                          Case{1.5, {0.27, 2.9}, 0.9, 400.0}, Case{1.8, {1.2, 7.0}, 0.3, 900.0}, Case{1.1, {4.0, 0.03}, 0.05, 1500.0}}) {
        for (const double wavelength : {380.0, 550.0, 700.0})
            for (const auto polarisation : {Polarisation::S, Polarisation::P}) {
                CAPTURE(c.n1);
                CAPTURE(c.n2.imag());
                CAPTURE(wavelength);
                const FilmSeries series = film_series(1.0, c.n1, c.n2, c.cos0, polarisation, 60);
                const double delta = 4.0 * std::numbers::pi * c.n1 * c.thickness * series.cos_film / wavelength;
                const Stack stack{1.0, {{c.n1, c.thickness}}, c.n2};
                const double exact = transfer_matrix(stack, wavelength, c.cos0, polarisation).reflectance;
                CHECK(evaluate(series, delta) == doctest::Approx(exact).epsilon(1e-10));
            }
    }
    CHECK_THROWS_AS(film_series(1.5, 1.0, {1.5, 0.0}, 0.2, Polarisation::S, 4), fxview::Error);  // evanescent film
}

TEST_CASE("a prepared stack: the lossless shortcut and shared phases give the general matrices' values") {
    // reflectances() multiplies real 4-number products and shares cos δ, sin δ between repeated
    // layers when every layer is lossless; response() always multiplies general complex matrices.
    // Both are the same characteristic-matrix method, so they agree to double rounding.
    std::vector<Stack> stacks;
    for (const int layers : {1, 2, 7, 16}) {
        Stack periodic{1.0, {}, Complex(1.52, 0.0)};
        for (int j = 1; j <= layers; ++j) periodic.layers.push_back({j % 2 == 1 ? Complex(2.35, 0.0) : Complex(1.38, 0.0), j % 2 == 1 ? 61.0 : 99.6});
        stacks.push_back(periodic);
    }
    stacks.push_back(Stack{1.0, {{Complex(1.33, 0.0), 420.0}, {Complex(1.7, 0.0), 15.0}, {Complex(1.33, 0.0), 420.0}}, Complex(0.27, 2.9)});
    stacks.push_back(Stack{1.0, {{Complex(1.5, 0.4), 80.0}, {Complex(2.0, 0.0), 120.0}}, Complex(1.5, 0.0)});  // absorbing layer
    stacks.push_back(Stack{1.6, {{Complex(1.2, 0.0), 100.0}, {Complex(1.4, 0.0), 60.0}}, Complex(1.5, 0.0)});  // evanescent past 48.6°
    for (const Stack& stack : stacks)
        for (const double cos0 : {1.0, 0.7, 0.31, 0.05})
            for (const double wavelength : {380.0, 523.0, 777.0}) {
                const PreparedStack prepared(stack, cos0);
                const auto [s, p] = prepared.reflectances(wavelength);
                CAPTURE(stack.layers.size());
                CAPTURE(cos0);
                CHECK(s == doctest::Approx(prepared.response(wavelength, Polarisation::S).reflectance).epsilon(1e-12));
                CHECK(p == doctest::Approx(prepared.response(wavelength, Polarisation::P).reflectance).epsilon(1e-12));
            }
}

TEST_CASE("a CD's diffraction orders: l_m is where the N-slit sum peaks, and the efficiencies conserve energy") {
    // Views over the hemisphere (θ 0..89°, φ 0..330°), wavelengths across the visible, CD and DVD spacings.
    const GratingOrderModel cd;
    for (const double spacing : {1600.0, 740.0})
        for (double theta = 0; theta < 90; theta += 11)
            for (double phi = 0; phi < 360; phi += 30)
                for (const double lambda : {380.0, 455.0, 550.0, 780.0}) {
                    CAPTURE(spacing); CAPTURE(theta); CAPTURE(phi); CAPTURE(lambda);
                    const double t = theta * std::numbers::pi / 180, p = phi * std::numbers::pi / 180;
                    const glm::dvec3 view(std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t));
                    const OrderRange range = propagating_orders(view, lambda, spacing);
                    // The range holds exactly the m whose l_m exists (brute force over m = -20..20).
                    for (int m = -20; m <= 20; ++m)
                        CHECK(order_incidence(view, m, lambda, spacing).has_value() == (m >= range.first && m <= range.last));
                    for (int m = range.first; m <= range.last; ++m) {
                        const glm::dvec3 l = *order_incidence(view, m, lambda, spacing);
                        CHECK(glm::length(l) == doctest::Approx(1.0).epsilon(kExact));
                        CHECK(l.z > 0);
                        // grating.hpp's convention, x = d (l + v)·g / λ: the tracks' phasors add up (x = m),
                        // and along the tracks the phase y = d (l + v)·t / λ vanishes (the segment's peak).
                        const double x = spacing * (l.x + view.x) / lambda;
                        CHECK(grating_intensity(x, 40) == doctest::Approx(1.0).epsilon(1e-9));  // 1e-9: sin near its zeros
                        CHECK(std::abs(l.y + view.y) < kExact);
                    }
                    // Σ η_m = the coating's reflectance, for any pit width and mirror share; none negative.
                    for (const double pit : {0.05, 0.35, 0.5, 0.95})
                        for (const double zero : {0.0, 0.35, 1.0}) {
                            GratingOrderModel model = cd;
                            model.spacing_nm = spacing, model.pit_fraction = pit, model.zero_order = zero;
                            const std::vector<double> eta = order_efficiencies(model, range);
                            double sum = 0;
                            for (const double e : eta) {
                                sum += e;
                                CHECK(e >= 0);
                            }
                            CHECK(sum == doctest::Approx(model.reflectance).epsilon(kExact));
                            if (range.first < range.last) CHECK(eta[size_t(-range.first)] == doctest::Approx(zero * model.reflectance));
                        }
                }
    // Light along the normal, d = 1600 nm: 500 nm leaves in order 1 at sin θ = λ/d = 0.3125 (Hecht eq. 10.61),
    // so a viewer there sees order +1 arriving from the normal (the order leaves along l_x = mλ/d − v_x).
    const glm::dvec3 view(-0.3125, 0, std::sqrt(1 - 0.3125 * 0.3125));
    const glm::dvec3 l = *order_incidence(view, -1, 500.0, 1600.0);
    CHECK(l.x == doctest::Approx(0.0).scale(1.0).epsilon(kExact));
    CHECK(l.z == doctest::Approx(1.0).epsilon(kExact));
    // Scalar theory's weights: with pits half the period, even orders vanish (sinc²(m/2) = 0 for even m ≠ 0).
    GratingOrderModel half = cd;
    half.pit_fraction = 0.5;
    const std::vector<double> eta = order_efficiencies(half, OrderRange{-3, 3});
    CHECK(eta[1] < 1e-30);  // m = -2
    CHECK(eta[5] < 1e-30);  // m = +2
    CHECK(eta[2] == doctest::Approx(eta[4]).epsilon(kExact));  // ±1 alike
    CHECK(eta[2] / eta[0] == doctest::Approx(9.0).epsilon(1e-12));  // sinc²(1/2) / sinc²(3/2) = 9
}

TEST_CASE("a sphere light's radiance through a softened order holds the point light's irradiance") {
    // ∫ L cos δ dω over the cap around a light at the zenith, in angles (dω = 2π sin δ dδ, the chord
    // c = 2 sin(δ/2)), by the midpoint rule: 200000 steps over at most 0.6 rad, error ~1e-10 where L
    // is smooth, and below 1e-7 with the ramp's kinks (each off by O(h²) in its step).
    const auto irradiance = [](double alpha, double width) {
        const int steps = 200000;
        const double edge = light_edge_chord(std::sin(alpha)), reach = 2 * std::asin(std::min(1.0, 0.5 * (edge + 0.5 * width))),
                     h = reach / steps;
        double sum = 0;
        for (int i = 0; i < steps; ++i) {
            const double d = (i + 0.5) * h;
            sum += sphere_light_radiance(2 * std::sin(d / 2), edge, width) * std::cos(d) * 2 * std::numbers::pi * std::sin(d) * h;
        }
        return sum;
    };
    for (const double alpha : {0.0, 0.01, 0.1, 0.26, 0.44, 1.0})
        for (const double width : {0.0, 1e-4, 0.01, 0.05, 0.2}) {
            if (alpha == 0 && width == 0) continue;  // a true point: no radiance to integrate
            CAPTURE(alpha); CAPTURE(width);
            CHECK(irradiance(alpha, width) == doctest::Approx(1.0).epsilon(1e-6));  // 1e-6: the quadrature's kinks, above
        }
    // The edge's chord against 2 sin(α/2) (the form without cancellation must not lose small lights).
    for (const double alpha : {1e-6, 0.26, 1.0, std::numbers::pi / 2})
        CHECK(light_edge_chord(std::sin(alpha)) == doctest::Approx(2 * std::sin(alpha / 2)).epsilon(kExact));
    // Sharp: the uniform disc 1 / (π sin²α) inside, nothing outside.
    const double edge = light_edge_chord(std::sin(0.26));
    CHECK(sphere_light_radiance(0.5 * edge, edge, 0) == doctest::Approx(1 / (std::numbers::pi * std::sin(0.26) * std::sin(0.26))).epsilon(kExact));
    CHECK(sphere_light_radiance(1.01 * edge, edge, 0) == 0.0);
}
