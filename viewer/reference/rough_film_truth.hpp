// The ground truth of a rough film under an environment (thinfilm.fx's Roughness): what the split
// form of effects/lib/film_roughness.glsl stands for, the lobe's integral with the film's reflectance
// at each direction's own half vector.
#pragma once
#include <functional>
#include <vector>

#include <glm/glm.hpp>

#include "reference/environment_reference.hpp"

namespace fxview::reference {

// The radiance at each nm of 360-830 that the film reflects towards v: the mean, weighted by the
// Phong lobe (r·l)^p about the mirror direction r over l with n·l > 0, of the environment's exact
// radiance L(l, λ) times reflectance(cos θ_h, λ), θ_h between v and the half vector of v and l.
// `samples` lobe-distributed directions (a Hammersley set turned by `seed`) and each disc light by its
// quadrature; the reflectance is evaluated at 33 angles spanning those of the directions and
// interpolated linearly between them.
std::vector<double> rough_film_radiance(const EnvironmentLookup& environment, const glm::dvec3& n, const glm::dvec3& v, double power,
                                        const std::function<double(double cos_h, int nm)>& reflectance, unsigned seed, int samples = 1024);

// The same under a uniform sky (no environment; thinfilm.fx's light spectrum from every direction):
// the mean over `samples` lobe-distributed directions above the surface of radiance(cos θ_h, λ), the
// light spectrum times the film there.
std::vector<double> rough_film_uniform(const glm::dvec3& n, const glm::dvec3& v, double power, const std::function<double(double cos_h, int nm)>& radiance,
                                       unsigned seed, int samples = 1024);

}  // namespace fxview::reference
