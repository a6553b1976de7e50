// Ground truth of the films (thin_film_truth.hpp).
#include "reference/thin_film_truth.hpp"

#include <cmath>
#include <numbers>
#include <vector>

#include "optics/prepared_stack.hpp"
#include "reference/lamp_image.hpp"
#include "reference/rough_film_truth.hpp"

namespace fxview::reference::thin_film {

// `compare --ground-truth` for the films under a spectral environment (Incidence = view): the
// physical film the technique stands for (`stack_at`: a single film, a free film, a stack),
// unpolarised, by characteristic matrices at every nm of 360-830, mirroring the environment's
// radiance from its model (environment:: exact weights, the sun a sharp disc, the spectra in double)
// in the mirror direction of the eye at the pixel's centre: independent of the weight cube, its
// bilinear reads and the techniques' formulas. Deterministic (its two estimates agree).

namespace {

// The reflectance of a film whose thickness is spread as a Gaussian of standard deviation `spread`
// about f.thickness, cut at 0 (no film is thinner): composite Simpson over ±6σ, steps of at most
// 360 / (32 n1) nm (a sixteenth of the fastest fringe's period at 360 nm). Independent of the
// technique's damped series.
double spread_reflectance(const Film& f, double spread, int nm, const StackAt& stack_at_nm) {
    const int intervals = 2 * static_cast<int>(std::ceil(6.0 * spread / (360.0 / (32.0 * f.n1))));
    const double step = 12.0 * spread / intervals;
    double sum = 0.0, weights = 0.0;
    for (int i = 0; i <= intervals; ++i) {
        const double z = -6.0 * spread + i * step, thickness = f.thickness + z;
        if (thickness < 0.0) continue;
        const double w = (i == 0 || i == intervals ? 1.0 : i % 2 == 1 ? 4.0 : 2.0) * std::exp(-0.5 * z * z / (spread * spread));
        Film g = f;
        g.thickness = thickness;
        sum += w * optics::transfer_matrix_reflectance(stack_at_nm(g, nm), nm, f.cos0);
        weights += w;
    }
    return weights > 0.0 ? sum / weights : 0.0;
}

}  // namespace

// `spread_thickness`: the technique reads ThicknessSpread (the Fourier films): the truth averages the
// film over it, under the environment and under the light spectrum alike.
// `film_at` / `surface`: the film at a pixel and the surface it lies on (BumpFresnelExact: tilted).
Reference with_sky_truth(Reference r, StackAt stack_at_nm, bool spread_thickness, FilmAt film_at, SurfaceAt surface) {
    r.truth = [shade = r.shade, stack_at_nm, spread_thickness, film_at, surface](const ShadingInput& in, const ReferenceContext& c, unsigned seed) {
        const Film f = film_at(in, c);
        const double spread = spread_thickness ? c.number("ThicknessSpread") : 0.0;
        if (!f.sky && !f.strata && !(spread > 0.0)) return shade(in, c);  // smooth, lit by the light spectrum: nothing the reference approximates
        const ShadingInput at = surface(in, c);
        const glm::dvec3 n = glm::normalize(at.normal), v = glm::normalize(in.camera - in.position);
        const glm::dvec3 weights = f.sky ? f.environment->exact_spectral_weights(2.0 * glm::dot(n, v) * n - v) : glm::dvec3(0.0);
        const SpectralSetup setup = spectral_setup(c), every_nm = every_nm_setup(c);
        const int light = static_cast<int>(c.number("LightSpectrum"));
        const auto film_at_angle = [&](double cos0, int nm) {
            Film g = f;
            g.cos0 = cos0;
            return spread > 0.0 ? spread_reflectance(g, spread, nm, stack_at_nm) : optics::transfer_matrix_reflectance(stack_at_nm(g, nm), nm, cos0);
        };
        if (f.strata) {
            // A rough film: the lobe's integral with the film at each direction's half vector (under the
            // environment, or a uniform sky of the light spectrum), and the sized light's over its surface.
            const double power = film_lobe_power(f.roughness);
            const auto lit_film = [&](double cos_h, int nm) { return spectral::packed_value(*setup.spectra, light, nm) * film_at_angle(cos_h, nm); };
            const std::vector<double> rough = f.sky ? rough_film_radiance(*f.environment, n, v, power, film_at_angle, seed)
                                                    : rough_film_uniform(n, v, power, lit_film, seed);
            ShadingInput surface_in = in;
            surface_in.normal = n;
            const double mirror_lamp = std::numbers::pi * scene_light_radiance(in, 2.0 * glm::dot(n, v) * n - v, in.footprint.x);
            const std::vector<double> lamp = rough_lamp_radiance(surface_in, n, v, power, mirror_lamp, lit_film);
            return to_rgba(integrate(every_nm, true, [&](int nm) {
                const size_t i = static_cast<size_t>(nm - lighting::SpectralForm::kFirstNm);
                return rough[i] + lamp[i];
            }), every_nm.mapping);
        }
        return to_rgba(integrate(every_nm, true, [&](int nm) {
            const double radiance = f.sky ? f.environment->exact_spectral_radiance(weights, nm) + f.lamp * spectral::packed_value(*setup.spectra, light, nm)
                                          : light_at(f, setup, light, nm);
            return radiance * (spread > 0.0 ? spread_reflectance(f, spread, nm, stack_at_nm)
                                            : optics::transfer_matrix_reflectance(stack_at_nm(f, nm), nm, f.cos0));
        }), every_nm.mapping);
    };
    // Without an environment a rough film (a uniform sky through its lobe) or a spread of thicknesses
    // still has an approximation to measure.
    r.truth_wanted = [spread_thickness](const ReferenceContext& c) {
        const bool rough = c.values.numbers.count("Roughness") && c.number("Roughness") > 0.0 && c.number("Incidence") == 0.0;
        return rough || (spread_thickness && c.number("ThicknessSpread") > 0.0);
    };
    r.truth_method = spread_thickness ? "the exact film mirroring the environment's model or lit by the light spectrum, averaged over its spread of "
                                        "thicknesses (an image: each direction's own uplifted spectrum; 1 nm, characteristic matrices, Simpson over ±6σ; "
                                        "rough: over its lobe, 1024 directions, the film at each half vector)"
                                      : "the exact film mirroring the environment's model (an image: each direction's own uplifted spectrum; 1 nm, "
                                        "characteristic matrices; rough: over its lobe, 1024 directions, the film at each half vector)";
    return r;
}

optics::Stack single_film_stack(const Film& f, int) { return optics::Stack{f.n0, {{f.n1, f.thickness}}, optics::Complex(f.n2, f.kappa)}; }
optics::Stack free_film_stack(const Film& f, int) { return optics::Stack{f.n0, {{f.n1, f.thickness}}, f.n0}; }

}  // namespace fxview::reference::thin_film
