// A tangent frame about a unit axis (Duff et al. 2017), built as the GLSL libraries build it, so
// that CPU references place their deterministic sample directions where the GPU does.
#pragma once
#include <glm/glm.hpp>

namespace fxview::reference {

inline void duff_frame(const glm::dvec3& axis, glm::dvec3& x, glm::dvec3& y) {
    const double s = axis.z >= 0.0 ? 1.0 : -1.0, a = -1.0 / (s + axis.z), b = axis.x * axis.y * a;
    x = glm::dvec3(1.0 + s * axis.x * axis.x * a, s * b, -s * axis.x);
    y = glm::dvec3(b, s + axis.y * axis.y * a, -axis.y);
}

}  // namespace fxview::reference
