// A thin film as thinfilm.fx sees it at one pixel (its indices, angles, thickness, stack, the light
// it mirrors, a rough film's strata): what the CPU references and the ground truth of the films share.
#pragma once
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "optics/thin_film.hpp"
#include "reference/environment_reference.hpp"
#include "reference/film_strata.hpp"
#include "reference/reference.hpp"
#include "reference/spectral_integration.hpp"

namespace fxview::reference::thin_film {

struct Film {
    double n0, n1, n2, kappa;
    double cos_light, cos_view, cos0;
    double cos0_spread;  // cos0's standard deviation over a rough film's lobe (0: smooth)
    double thickness;  // nm at this pixel (layer A of a stack)
    optics::Stack stack;
    double dispersion_a, dispersion_b;  // Cauchy B of layers A and B (nm²), MultiLayer only
    // Under the environment's spectral form (the built-in sky) with Incidence = view: its weights in
    // the mirror direction of the eye, which light the film instead of the light spectrum.
    std::optional<glm::dvec3> sky;
    std::optional<EnvironmentLookup> environment;
    // With Incidence = view: a sized scene light's image in the mirror direction, over the uniform
    // sky's radiance (π x its radiance per unit light strength), added to the light spectrum.
    double lamp = 0;
    double roughness = 0;  // Roughness: the environment seen through a Phong lobe (film_roughness.glsl)
    // How far GL's filtering leaves a rough film's sky weights open (cube corners, sub-texel precision).
    double sky_seam = 0;
    // A rough film's strata of its lobe (film_strata.hpp); each technique sums its colour over them,
    // each stratum a Film of its own angle, weights and `share` of a uniform sky's and a lamp's light.
    std::optional<FilmStrata> strata;
    double share = 1.0;
};

// The films a technique sums (thinfilm.fx film_stratum): the pixel's film, or a rough film's strata.
std::vector<Film> film_strata(const Film& f);

// The light at `nm`: the light spectrum, or the sky seen in the mirror direction, and the lamp's
// image (thinfilm.fx light_at).
double light_at(const Film& f, const SpectralSetup& s, int light, int nm);

// The film at a pixel, from the effect's parameters.
Film film(const ShadingInput& in, const ReferenceContext& c);
using FilmAt = Film (*)(const ShadingInput&, const ReferenceContext&);

// The stack at one wavelength: Cauchy's n + B / λ² for the films (MultiLayer).
optics::Stack stack_at(const Film& f, double nm);

// The height field of BumpFresnelExact, h = A sin(2πfu) sin(2πfv): the film under the normal tilted
// by -∇h in the tangent frame (T, B = N x T, N), thickened by WaveThickness · h.
ShadingInput bumped_input(const ShadingInput& in, const ReferenceContext& c);
Film bumped_film(const ShadingInput& in, const ReferenceContext& c);

}  // namespace fxview::reference::thin_film
