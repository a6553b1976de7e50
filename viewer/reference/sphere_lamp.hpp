// wavelength.fx's lamp as a sphere (effects/lib/sphere_lamp.glsl): the factors that replace the point
// light's cos θ, (r·v)^p and (n·h)^p, as the GPU computes them, and the integrals they stand for.
#pragma once
#include <glm/glm.hpp>

namespace fxview::reference {

struct LampFactors {
    double lambert = 0, phong = 0, blinn = 0;
};

// The GPU's: Snyder's exact horizon-clipped irradiance over the point's, and the lobes at the same
// points of the disc (`rounding`: relative float error of each lobe's base, raised to the power, and of the
// count of points; either sign).
// `l` the unit direction to the lamp's centre, sin_alpha its angular radius' sine (> 0).
LampFactors sphere_lamp_factors(const glm::dvec3& n, const glm::dvec3& v, const glm::dvec3& l, double sin_alpha, double power, bool lobes,
                                double rounding = 0.0);

// The same integrals over the disc by an independent rule: 128 rings equally spaced in angle (weighted
// by sin) x 256 azimuths, every point's cos θ and lobes, horizon included.
LampFactors sphere_lamp_integral(const glm::dvec3& n, const glm::dvec3& v, const glm::dvec3& l, double sin_alpha, double power);

}  // namespace fxview::reference
