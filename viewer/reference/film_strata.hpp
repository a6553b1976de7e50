// A rough film's lobe split into four strata by the angle the film is seen at (v·h): CPU twin of
// film_rough_strata in effects/lib/film_roughness.glsl, from its documented arithmetic.
#pragma once
#include <array>

#include <glm/glm.hpp>

#include "reference/environment_reference.hpp"
#include "reference/reference.hpp"

namespace fxview::reference {

struct FilmStrata {
    std::array<double, 4> cosine{}, spread{}, share{};  // mean v·h (light-weighted), its deviation, part of the directions
    std::array<glm::dvec3, 4> weights{};               // the environment's weights per stratum (sum: the lobe's mean)
    std::array<double, 4> lamp{};                      // the scene's sized light per stratum, in the uniform sky's units
    double seam = 0;                                   // how far GL's filtering leaves the weights open
    bool empty(size_t s) const { return share[s] == 0.0 && weights[s] == glm::dvec3(0.0) && lamp[s] == 0.0; }
};

// A rough film's lobe (film_roughness.glsl film_lobe_power): Phong of p = (1/α² − 1)/2 for
// α = roughness², within [1, 1e5].
double film_lobe_power(double roughness);

// The lobe's power as `points` points spread over a light of `solid` angle see it: widened to a
// standard deviation of at least 0.6 of their spacing (film_roughness.glsl film_points_lobe_power).
double film_points_lobe_power(double power, double solid, int points);

// A direction drawn as the Phong lobe of `power` about unit r (frame x, y, r) for a point u of the
// unit square: cos = (1 − u.x)^(1/(p+1)) about r, azimuth 2π u.y; `cosine` gets that cos.
glm::dvec3 phong_lobe_direction(const glm::dvec3& r, const glm::dvec3& x, const glm::dvec3& y, const glm::dvec2& u, double power, double* cosine = nullptr);

// Phong's (r·l)^p, 0 behind r (at p = 0 too).
double phong_lobe(const glm::dvec3& r, const glm::dvec3& l, double power);

// The mean and standard deviation of v·h over 32 of the lobe's directions above the surface
// (film_rough_cosine): where the strata's edges go.
glm::dvec2 film_rough_cosine(const glm::dvec3& n, const glm::dvec3& v, double power);

// The Phong lobe of `power` about the mirror direction of v, split at μ + σ (−0.674, 0, 0.674) of
// `seen` = (μ, σ) of v·h. `sky`: the spectral environment seen through it (filtered gather, disc
// lights by their points); null: a uniform light, every direction alike.
// `in`: the pixel, for the scene's sized light seen through the lobe at its own points (16 over a
// sphere, a flat light's 34); `mirror_lamp`: its image in the mirror direction, for a lobe with no
// direction above the surface.
FilmStrata film_rough_strata(const glm::dvec3& n, const glm::dvec3& v, double power, const glm::dvec2& seen, const EnvironmentLookup* sky,
                             const ShadingInput& in, double mirror_lamp);

}  // namespace fxview::reference
