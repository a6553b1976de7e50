// Thin films from viewer/optics (DOMAIN.md §3): the light spectrum times the film's reflectance at
// each sampled wavelength, integrated like every spectral reference. The exact techniques
// (FresnelExact, Bubble, MultiLayer*) are checked against characteristic matrices, a method the
// GLSL does not use (it runs Airy's sum and Hirayama's recursion); the thesis' approximations
// against their documented formulas in double precision.
#include "reference/thin_film_reference.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <numbers>
#include <optional>

#include "optics/prepared_stack.hpp"
#include "optics/thesis_models.hpp"
#include "optics/thin_film.hpp"
#include "reference/environment_reference.hpp"
#include "reference/film_fourier.hpp"
#include "reference/lamp_image.hpp"
#include "reference/film_strata.hpp"
#include "reference/rough_film_truth.hpp"
#include "reference/spectral_integration.hpp"
#include "reference/tangent_frame.hpp"
#include "reference/thin_film_pixel.hpp"
#include "reference/thin_film_truth.hpp"
#include "lighting/image_based_lighting.hpp"

namespace fxview::reference {
namespace {

using namespace thin_film;

// A film's reflectance over the wavelength, set up once per pixel: what does not depend on the
// wavelength (a stack's angles and admittances) is worked out before the spectral loop.
using AtWavelength = std::function<double(double nm)>;
using Reflectance = std::function<AtWavelength(const Film&)>;

template <typename Model>
Reflectance per_wavelength(Model model) {
    return [model](const Film& f) { return AtWavelength([model, f](double nm) { return model(f, nm); }); };
}

// Unpolarised reflectance of a stack by characteristic matrices (optics::PreparedStack).
template <typename StackOf>
Reflectance by_matrices(StackOf stack_of) {
    return [stack_of](const Film& f) {
        return AtWavelength([prepared = std::make_shared<const optics::PreparedStack>(stack_of(f), f.cos0)](double nm) {
            const auto [s, p] = prepared->reflectances(nm);
            return 0.5 * (s + p);
        });
    };
}

// The light spectrum times the film's reflectance, integrated against the CMFs.
std::array<double, 4> film_colour(const Film& f, const ReferenceContext& c, const Reflectance& reflectance) {
    const SpectralSetup s = spectral_setup(c);
    const int light = static_cast<int>(c.number("LightSpectrum"));
    spectral::Vec3 xyz{0, 0, 0};
    for (const Film& stratum : film_strata(f)) {
        const AtWavelength at = reflectance(stratum);
        const spectral::Vec3 part = integrate(s, false, [&](int nm) { return light_at(stratum, s, light, nm) * at(nm); });
        for (size_t i = 0; i < 3; ++i) xyz[i] += part[i];
    }
    return to_rgba(xyz, s.mapping);
}

// The phase's float rounding is independent from wavelength to wavelength, so the colour error
// averages over the samples. A light that puts its power into few wavelengths (a fluorescent line
// spectrum, summed at its 5 nm lines), a narrow range or coarse steps average over fewer: the bound
// grows with the square root of the drop in the effective number of samples (Σw)²/Σw², w = light x
// CMF, against an equal-energy light over the default range.
double averaging_factor(const ReferenceContext& c) {
    const SpectralSetup s = spectral_setup(c);
    const int light = static_cast<int>(c.number("LightSpectrum"));
    // The equal-energy light over the default range (360-830 nm every nm), where the bound was measured.
    const auto effective_samples = [&](bool flat) {
        double sum = 0, squares = 0;
        const int lower = flat ? 360 : s.lower, upper = flat ? 830 : s.upper, steps = flat ? 1 : s.steps;
        for (int nm = lower; nm <= upper; nm += steps) {
            const spectral::Vec3 cmf = spectral::cmf_value(*s.cmf, s.observer, nm);
            const double w = (flat ? 1.0 : spectral::packed_value(*s.spectra, light, nm)) * (cmf[0] + cmf[1] + cmf[2]);
            sum += w;
            squares += w * w;
        }
        return squares > 0 ? sum * sum / squares : 1.0;
    };
    return std::max(1.0, std::sqrt(effective_samples(true) / effective_samples(false)));
}

// The GPU forms each phase (4π n d cos θ / λ per layer) and cosine in float: ~1e-6 relative of a
// phase after the handful of operations that form it, ~5e-7 absolute in the cosines. Where the
// reflectance is steep in them (a multilayer's resonances, a single sampled wavelength, the finesse
// near grazing incidence) that moves the colour by more than the averaged bound: the slack is the
// largest colour change when every thickness scales by 1 ± 1e-6 or the cosines move by ± 5e-7.
using FilmColour = std::function<std::array<double, 4>(const Film&)>;

double phase_sensitivity(const Film& at, const FilmColour& colour) {
    const std::array<double, 4> base = colour(at);
    double change = 0;
    const auto compare = [&](const Film& f) {
        const std::array<double, 4> moved = colour(f);
        for (size_t i = 0; i < 3; ++i) change = std::max(change, std::abs(moved[i] - base[i]));
    };
    for (const double sign : {-1.0, 1.0}) {
        Film thicker = at;
        thicker.thickness *= 1.0 + sign * 1e-6;
        for (optics::Layer& layer : thicker.stack.layers) layer.thickness_nm *= 1.0 + sign * 1e-6;
        compare(thicker);
        Film turned = at;
        for (double* cosine : {&turned.cos0, &turned.cos_light, &turned.cos_view}) *cosine = std::clamp(*cosine + sign * 5e-7, 0.0, 1.0);
        if (turned.strata)
            for (double& cosine : turned.strata->cosine) cosine = std::clamp(cosine + sign * 5e-7, 0.0, 1.0);
        compare(turned);
        if (at.sky && at.sky_seam > 0) {  // a rough film's filtered sky weights, as open as GL leaves them
            Film filtered = at;
            *filtered.sky += sign * at.sky_seam;
            if (filtered.strata)
                for (glm::dvec3& w : filtered.strata->weights) w += sign * at.sky_seam;
            compare(filtered);
        }
    }
    return change;
}

Reference make(Reflectance reflectance, double tolerance, std::string why, FilmAt film_at = film) {
    Reference r;
    r.shade = [reflectance, film_at](const ShadingInput& in, const ReferenceContext& c) { return film_colour(film_at(in, c), c, reflectance); };
    r.slack = [reflectance, film_at](const ShadingInput& in, const ReferenceContext& c) {
        return phase_sensitivity(film_at(in, c), [&](const Film& f) { return film_colour(f, c, reflectance); });
    };
    r.tolerance = tolerance;
    // Measured at the default Brightness 2 with automatic k; a brighter output scales the error alike.
    r.tolerance_for = [tolerance](const ReferenceContext& c) { return tolerance * averaging_factor(c) * output_gain(spectral_setup(c), 2.0); };
    r.why = std::move(why) + "; scaled by sqrt(effective samples of an equal-energy light over 360-830 nm / of the light over "
                             "the range used) and by the output's gain over Brightness 2 with automatic k; slack: the colour change "
                             "when thicknesses scale by 1 +- 1e-6 or the cosines move by +- 5e-7 (float phases and angles)";
    return r;
}

// Near grazing incidence r -> 1 and an etalon's finesse F = 4R/(1 - R)² grows without bound; the
// reflectance's slope with respect to the phase grows like sqrt(F) and amplifies float rounding there.
const char* kFinesseWhy =
    "as for the other films, but near grazing incidence (silhouettes) the finesse 4R/(1-R)^2 of the film grows "
    "without bound and amplifies the float phase error: measured up to 4e-5 there on llvmpipe (mostly ~1e-6)";

const char* kPhaseWhy =
    "float32 phases of up to ~60 rad (4 pi n d cos / lambda for micrometre films) carry ~1e-5 rad of rounding, "
    "and the reflectance follows the phase with a slope below 1; summed over 471 wavelengths the colour error "
    "stays near 1e-5 (measured on llvmpipe, docs/cpu-reference.md)";

// Eq. 62's frac() jumps by 1 where 2 d n cos / lambda crosses an integer. The GPU's value of that
// argument is a few float roundings off (~1e-6 relative); at wavelengths closer than that to a jump
// either side is right, and the colour may differ by that wavelength's whole contribution.
// `listing_chain`: the refracted cosine is formed as Code 13 prints it, cos(asin(r · sin(acos(c)))),
// whose float trigonometry errs far more than the port's sqrt form (whose few roundings the 4e-6
// relative window covers). Bounds, twice what llvmpipe's functions were measured to err over [0, 1]
// against double (2026-12-06: acos 1.6e-4 rad, asin 3.9e-4 rad, r · sin(acos(c)) 7.5e-5):
constexpr double kAcosError = 3.2e-4, kAsinError = 8e-4, kSineChainError = 1.5e-4;

double path_difference_slack(const ShadingInput& in, const ReferenceContext& c, bool listing_chain = false) {
    const SpectralSetup s = spectral_setup(c);
    const int light = static_cast<int>(c.number("LightSpectrum"));
    const Film f = film(in, c);
    double relative = 4e-6;
    bool anything = false;  // the cosine's error may reach 0: every wavelength may take either side
    if (listing_chain) {
        // β = asin(x), x = r sin α: δβ = δasin + (δx + r cos α δacos) / cos β, and δ(cos β) = sin β δβ.
        const double r = f.n0 / f.n1, sine = std::sqrt(std::max(1.0 - f.cos_light * f.cos_light, 0.0));
        const double cos_beta = std::sqrt(std::max(1.0 - r * r * sine * sine, 0.0));
        const double error = cos_beta > 0 ? std::sqrt(1.0 - cos_beta * cos_beta) * (kAsinError + (kSineChainError + r * f.cos_light * kAcosError) / cos_beta)
                                          : 1.0;
        // Past the critical angle the listing's cos(asin(1)) is ±4e-8 in float, and frac() of it 0 or nearly 1.
        anything = cos_beta <= error;
        relative += anything ? 0.0 : error / cos_beta;
    }
    return colour_uncertainty(s, [&](int nm) {
        if (anything) return light_at(f, s, light, nm);
        const double cycles = optics::thesis::path_difference(f.n0, f.n1, f.thickness, nm, f.cos_light, f.cos_view).cycles;
        // frac() jumps by 1 at 1, 2, ...; at 0 it is continuous (the argument is never negative).
        // Elsewhere it follows its argument with slope 1: an uncertain argument moves it as much.
        const bool on_jump = std::round(cycles) >= 1.0 && std::abs(cycles - std::round(cycles)) < relative * cycles;
        return light_at(f, s, light, nm) * (on_jump ? 1.0 : listing_chain ? relative * cycles : 0.0);
    });
}

// The Fourier techniques (FresnelFourier, BubbleFourier): the interference series in double, its
// coefficients from optics::film_series (the four Fresnel amplitudes, where the GLSL uses Stokes'
// relations), each term's F(m D) from the same table the GPU reads, interpolated in double, and the
// same stopping rule. Where no series exists (the film past its critical angle) both take the exact
// sum at every nm over 360-830 with 1 / Σ ȳ: here by characteristic matrices.
// One stratum's XYZ (a smooth film's whole), with the brightness.
spectral::Vec3 fourier_xyz(const Film& f, const ReferenceContext& c, optics::Complex substrate) {
    const SpectralSetup setup = spectral_setup(c);
    const int light = static_cast<int>(c.number("LightSpectrum"));
    const int polarisation = static_cast<int>(c.number("Polarisation"));
    SeriesTechnique technique;
    technique.order = static_cast<int>(c.number("SeriesOrder"));
    technique.weight_s = polarisation == 2 ? 0.0 : polarisation == 1 ? 1.0 : 0.5;
    technique.weight_p = polarisation == 1 ? 0.0 : 1.0 - technique.weight_s;
    const reference::SingleFilm film{f.n0, f.n1, substrate, f.thickness, f.cos0, c.number("ThicknessSpread"), f.cos0_spread};
    // Under the sky: the weighted series of its three spectra (environment:fourier), as on the GPU.
    // A lamp's image besides the sky (another spectrum): the exact sum; without the sky it has the
    // light's own spectrum and scales the series.
    const auto series = f.sky ? (f.lamp > 0 ? std::nullopt
                                            : film_xyz_fourier_table(*f.environment->spectral_fourier(), setup.observer,
                                                                     TableLight{0, 3, {f.sky->x, f.sky->y, f.sky->z}}, film, technique))
                              : film_xyz_fourier_table(c.generated("FilmFourier"), setup.observer,
                                                       TableLight{light, 1, {f.share + f.lamp, 0.0, 0.0}}, film, technique);
    if (series) {
        spectral::Vec3 xyz = *series;
        for (double& v : xyz) v *= setup.brightness;
        return xyz;
    }
    const SpectralSetup every_nm = every_nm_setup(c);
    const optics::Stack stack{f.n0, {{f.n1, f.thickness}}, substrate};
    return integrate(every_nm, true, [&](int nm) {
        return light_at(f, setup, light, nm) *
               (technique.weight_s * optics::transfer_matrix(stack, nm, f.cos0, optics::Polarisation::S).reflectance +
                technique.weight_p * optics::transfer_matrix(stack, nm, f.cos0, optics::Polarisation::P).reflectance);
    });
}

std::array<double, 4> fourier_colour(const Film& f, const ReferenceContext& c, optics::Complex substrate) {
    spectral::Vec3 xyz{0, 0, 0};
    for (const Film& stratum : film_strata(f)) {
        const spectral::Vec3 part = fourier_xyz(stratum, c, substrate);
        for (size_t i = 0; i < 3; ++i) xyz[i] += part[i];
    }
    return to_rgba(xyz, spectral_setup(c).mapping);
}

Reference fourier_reference(bool free_film) {
    const auto substrate = [free_film](const Film& f) { return free_film ? optics::Complex(f.n0, 0.0) : optics::Complex(f.n2, f.kappa); };
    Reference r;
    r.shade = [substrate](const ShadingInput& in, const ReferenceContext& c) {
        const Film f = film(in, c);
        return fourier_colour(f, c, substrate(f));
    };
    r.slack = [substrate](const ShadingInput& in, const ReferenceContext& c) {
        return phase_sensitivity(film(in, c), [&](const Film& f) { return fourier_colour(f, c, substrate(f)); });
    };
    r.tolerance = 5e-5;
    r.tolerance_for = [](const ReferenceContext& c) { return 5e-5 * output_gain(spectral_setup(c), 2.0); };
    r.why = "float32 look-ups of the same table and float phases D ν of up to ~100 cycles; a handful of terms, each "
            "below 1e-5 of rounding, so no averaging over wavelengths is needed (measured on llvmpipe); the fallback "
            "past the critical angle sums 471 wavelengths as FresnelExact does; slack: the colour change when thicknesses "
            "scale by 1 +- 1e-6 or the cosines move by +- 5e-7 (float phases and angles)";
    return r;
}

}  // namespace

std::map<std::string, Reference> thin_film_references() {
    std::map<std::string, Reference> all;
    Reference path = make(per_wavelength([](const Film& f, double nm) {
        return optics::thesis::path_difference(f.n0, f.n1, f.thickness, nm, f.cos_light, f.cos_view).intensity;
    }), 5e-5, std::string(kPhaseWhy) + "; pixels where a wavelength sits on frac()'s jump get that wavelength's share as slack");
    path.slack = [phase = path.slack](const ShadingInput& in, const ReferenceContext& c) {
        return phase(in, c) + path_difference_slack(in, c);
    };
    all.emplace("PathDifference", with_sky_truth(path, single_film_stack));
    // The thesis' own Cg (effects/legacy/thinfilm.cgfx) forms the refracted cosine as Code 13 prints
    // it, cos(asin(n0/n1 · sin(acos(c)))): the same value and tolerance as the port, and each pixel's
    // slack what that chain's float error can move (path_difference_slack).
    Reference listing = path;
    listing.slack = [phase = path.slack](const ShadingInput& in, const ReferenceContext& c) {
        return phase(in, c) + path_difference_slack(in, c, true);
    };
    listing.why = std::string(kPhaseWhy) + "; the listing's float acos/asin chain errs by up to 8e-4 rad (twice llvmpipe's measured "
                  "error), amplified near the film's critical angle: each wavelength's frac() may move by what that makes of "
                  "its argument, or next to a jump (and past the critical angle) by its whole share (slack)";
    all.emplace("legacy:PathDifference", std::move(listing));

    const Reflectance durikovic =
        per_wavelength([](const Film& f, double nm) { return optics::thesis::durikovic(f.n0, f.n1, f.n2, f.thickness, nm, f.cos0); });
    all.emplace("Fresnel", with_sky_truth(make(durikovic, 5e-5, kPhaseWhy), single_film_stack));
    all.emplace("FresnelFaster", with_sky_truth(make(durikovic, 5e-5, kPhaseWhy), single_film_stack));
    all.emplace("FresnelAlternative", with_sky_truth(make(per_wavelength([](const Film& f, double nm) {
        return optics::thesis::alternative(f.n0, f.n1, f.n2, f.thickness, nm, f.cos0);
    }), 5e-5, kPhaseWhy), single_film_stack));
    all.emplace("FabryPerot", with_sky_truth(make(per_wavelength([](const Film& f, double nm) {
        return optics::thesis::fabry_perot(f.n0, f.n1, f.thickness, nm, f.cos0);
    }), 1e-4, kFinesseWhy), free_film_stack));

    // Exact models against characteristic matrices.
    const Reflectance single_film =
        by_matrices([](const Film& f) { return optics::Stack{f.n0, {{f.n1, f.thickness}}, optics::Complex(f.n2, f.kappa)}; });
    all.emplace("FresnelExact", with_sky_truth(make(single_film, 5e-5, kPhaseWhy), single_film_stack));
    // Bump mapping (eq. 69): the same film under a wave-tilted normal, thickened at the crests.
    Reference bump = make(single_film, 5e-5, kPhaseWhy, bumped_film);
    // The GPU reduces the wave's phase f·uv to one period in float; its rounding (an ulp of f·u, 1e-6
    // at 13.5 waves) moves slope and thickness, by an amount that grows with the waves' steepness
    // (slope A·2πf reaches 40). The slack is the colour change that shifting u or v by that much causes.
    bump.slack = [single_film, phase = bump.slack](const ShadingInput& in, const ReferenceContext& c) {
        const double frequency = c.number("WaveFrequency");
        const std::array<double, 4> at = film_colour(bumped_film(in, c), c, single_film);
        double slack = 0;
        for (int axis = 0; axis < 2; ++axis) {
            const float waves = static_cast<float>(frequency * in.uv[axis]);
            const double ulp = std::nextafter(waves, std::numeric_limits<float>::infinity()) - waves;
            for (const double sign : {-1.0, 1.0}) {
                ShadingInput moved = in;
                moved.uv[axis] += sign * ulp / frequency;
                const std::array<double, 4> shifted = film_colour(bumped_film(moved, c), c, single_film);
                for (int i = 0; i < 3; ++i) slack = std::max(slack, std::abs(shifted[static_cast<size_t>(i)] - at[static_cast<size_t>(i)]));
            }
        }
        return slack + phase(in, c);
    };
    all.emplace("BumpFresnelExact", with_sky_truth(std::move(bump), single_film_stack, false, bumped_film, bumped_input));
    all.emplace("Bubble", with_sky_truth(make(by_matrices([](const Film& f) { return free_film_stack(f, 0); }), 1e-4, kFinesseWhy), free_film_stack));
    // With dispersion the indices, and so the angles, change with the wavelength: one stack per nm.
    const Reflectance fixed_stack = by_matrices([](const Film& f) { return f.stack; });
    const Reflectance dispersive_stack =
        per_wavelength([](const Film& f, double nm) { return optics::transfer_matrix_reflectance(stack_at(f, nm), nm, f.cos0); });
    const StackAt dispersed = [](const Film& f, int nm) { return stack_at(f, nm); };
    all.emplace("MultiLayer", with_sky_truth(make([fixed_stack, dispersive_stack](const Film& f) {
        return f.dispersion_a == 0.0 && f.dispersion_b == 0.0 ? fixed_stack(f) : dispersive_stack(f);
    }, 5e-5, kPhaseWhy), dispersed));
    all.emplace("MultiLayerFaster", with_sky_truth(make(fixed_stack, 5e-5, kPhaseWhy), dispersed));
    all.emplace("FresnelFourier", with_sky_truth(fourier_reference(false), single_film_stack, true));
    all.emplace("BubbleFourier", with_sky_truth(fourier_reference(true), free_film_stack, true));
    return all;
}

}  // namespace fxview::reference
