// The film at a pixel (thin_film_pixel.hpp), as thinfilm.fx and its headers form it.
#include "reference/thin_film_pixel.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "reference/lamp_image.hpp"

namespace fxview::reference::thin_film {

std::vector<Film> film_strata(const Film& f) {
    if (!f.strata) return {f};
    std::vector<Film> strata;
    for (size_t s = 0; s < 4; ++s) {
        if (f.strata->empty(s)) continue;
        Film g = f;
        g.cos0 = f.strata->cosine[s];
        g.cos0_spread = f.strata->spread[s];
        g.share = f.strata->share[s];
        g.lamp = f.strata->lamp[s];
        if (g.sky) g.sky = f.strata->weights[s];
        strata.push_back(g);
    }
    return strata;
}

double light_at(const Film& f, const SpectralSetup& s, int light, int nm) {
    const double spectrum = spectral::packed_value(*s.spectra, light, nm);
    return (f.sky ? f.environment->spectral_radiance(*f.sky, nm) : f.share * spectrum) + f.lamp * spectrum;
}

Film film(const ShadingInput& in, const ReferenceContext& c) {
    Film f{};
    f.n0 = c.number("OuterIndex");
    f.n1 = c.number("FilmIndex");
    f.n2 = c.number("SubstrateIndex");
    f.kappa = c.number("SubstrateKappa");
    const glm::dvec3 n = glm::normalize(in.normal);
    f.cos_light = std::clamp(glm::dot(n, glm::normalize(in.light - in.position)), 0.0, 1.0);
    f.cos_view = std::clamp(glm::dot(n, glm::normalize(in.camera - in.position)), 0.0, 1.0);
    f.roughness = c.values.numbers.count("Roughness") ? c.number("Roughness") : 0.0;  // the thesis' own listings have none
    const glm::dvec3 v = glm::normalize(in.camera - in.position), mirror = 2.0 * glm::dot(n, v) * n - v;
    const bool view = c.number("Incidence") == 0.0;
    const glm::dvec2 seen = view && f.roughness > 0 ? film_rough_cosine(n, v, film_lobe_power(f.roughness)) : glm::dvec2(f.cos_view, 0.0);
    f.cos0 = view ? seen.x : f.cos_light;
    f.cos0_spread = view ? seen.y : 0.0;
    f.environment = EnvironmentLookup::from(c);
    const bool under_sky = view && f.environment && f.environment->spectral() && c.environment->intensity > 0;
    // The GPU's blur of the lamp's image (how far the mirror direction turns across the pixel), as captured.
    if (view) f.lamp = std::numbers::pi * scene_light_radiance(in, mirror, in.footprint.x);
    if (view && f.roughness > 0) {
        f.strata = film_rough_strata(n, v, film_lobe_power(f.roughness), seen, under_sky ? &*f.environment : nullptr, in, f.lamp);
        f.lamp = f.strata->lamp[0] + f.strata->lamp[1] + f.strata->lamp[2] + f.strata->lamp[3];
        f.sky_seam = f.strata->seam;
        if (under_sky) f.sky = f.strata->weights[0] + f.strata->weights[1] + f.strata->weights[2] + f.strata->weights[3];
    } else if (under_sky) {
        f.sky = f.environment->spectral_weights(mirror);
    }
    // An inverted paraboloid over the texture square, peaking at its centre (fig. 27).
    const glm::dvec2 centred = 2.0 * in.uv - 1.0;
    f.thickness = c.number("Thickness") + c.number("Variation") * std::max(1.0 - glm::dot(centred, centred), 0.0);
    // The stack: odd layers (from the top) are the film A, even ones B.
    f.stack.outer = f.n0;
    f.stack.substrate = optics::Complex(f.n2, f.kappa);
    const int layers = std::clamp(static_cast<int>(c.number("Layers")), 1, 16);
    for (int j = 1; j <= layers; ++j)
        f.stack.layers.push_back(j % 2 == 1 ? optics::Layer{f.n1, f.thickness}
                                            : optics::Layer{c.number("SecondIndex"), c.number("SecondThickness")});
    f.dispersion_a = c.number("FilmDispersion");
    f.dispersion_b = c.number("SecondDispersion");
    return f;
}

optics::Stack stack_at(const Film& f, double nm) {
    optics::Stack stack = f.stack;
    for (size_t j = 0; j < stack.layers.size(); ++j) stack.layers[j].index += (j % 2 == 0 ? f.dispersion_a : f.dispersion_b) / (nm * nm);
    return stack;
}

ShadingInput bumped_input(const ShadingInput& in, const ReferenceContext& c) {
    const double amplitude = c.number("WaveAmplitude"), w = 2.0 * std::numbers::pi * c.number("WaveFrequency");
    const glm::dvec3 n = glm::normalize(in.normal);
    const glm::dvec3 t = glm::normalize(in.tangent - n * glm::dot(n, in.tangent));
    const glm::dvec3 b = glm::cross(n, t);
    const glm::dvec2 phase = w * in.uv;
    const glm::dvec2 slope = amplitude * w * glm::dvec2(std::cos(phase.x) * std::sin(phase.y), std::sin(phase.x) * std::cos(phase.y));
    ShadingInput tilted = in;
    tilted.normal = -slope.x * t - slope.y * b + n;
    return tilted;
}

Film bumped_film(const ShadingInput& in, const ReferenceContext& c) {
    const double amplitude = c.number("WaveAmplitude");
    const glm::dvec2 phase = 2.0 * std::numbers::pi * c.number("WaveFrequency") * in.uv;
    Film f = film(bumped_input(in, c), c);
    f.thickness = std::max(f.thickness + c.number("WaveThickness") * amplitude * std::sin(phase.x) * std::sin(phase.y), 0.0);
    return f;
}

}  // namespace fxview::reference::thin_film
