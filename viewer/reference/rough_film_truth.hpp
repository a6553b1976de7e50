// The ground truth of a rough film under an environment (thinfilm.fx's Roughness): what the split
// form of effects/lib/film_roughness.glsl stands for, the lobe's integral with the film's reflectance
// at each direction's own half vector.
#pragma once
#include <functional>
#include <vector>

#include <glm/glm.hpp>

#include "reference/environment_reference.hpp"
#include "reference/reference.hpp"

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

// The scene's sized light (a sphere, disc or rectangle) through the same lobe: its exact radiance over
// a fine grid of cells (a sphere's cone 32 rings of equal solid angle x 64, a disc 32 x 64, a
// rectangle 48 x 48), each weighing π L ΔΩ (r·l)^p / mass, the mass the lobe's integral above the
// surface (4096 of its directions), in the uniform sky's units; `radiance` the light spectrum times
// the film at the cell's own half vector. `mirror_lamp`: the lamp's image in the mirror direction,
// taken at the eye's angle where no direction of the lobe lies above the surface.
std::vector<double> rough_lamp_radiance(const ShadingInput& in, const glm::dvec3& n, const glm::dvec3& v, double power, double mirror_lamp,
                                        const std::function<double(double cos_h, int nm)>& radiance);

}  // namespace fxview::reference
