// Float cube maps in memory for environment lighting, in OpenGL's conventions (GL 4.5 table 8.19):
// faces +X -X +Y -Y +Z -Z, texel (x, y) of a face at s = (x + ½) / size, t = (y + ½) / size, row 0
// being t = 0, as gl/texture_upload.hpp uploads cube faces.
#pragma once
#include <array>
#include <vector>

#include <glm/glm.hpp>

namespace fxview::lighting {

struct FloatCube {
    int size = 0;
    std::array<std::vector<glm::vec3>, 6> faces;

    explicit FloatCube(int size_ = 0);
    glm::vec3& at(int face, int x, int y) { return faces[static_cast<size_t>(face)][static_cast<size_t>(y) * size + x]; }
    const glm::vec3& at(int face, int x, int y) const { return faces[static_cast<size_t>(face)][static_cast<size_t>(y) * size + x]; }
};

// GL 4.5 table 8.19: the major axis picks the face, s and t in [0, 1] the place on it.
struct CubeFace {
    int face;
    double s, t;
};
CubeFace select_cube_face(const glm::dvec3& direction);
// The (unnormalised) direction through face coordinates s, t in [0, 1].
glm::dvec3 cube_direction(int face, double s, double t);
// The unit direction through the centre of texel (x, y).
glm::dvec3 texel_direction(int face, int x, int y, int size);
// The solid angle of texel (x, y) (exact, by the area formula of the projected square).
double texel_solid_angle(int x, int y, int size);

// Bilinear lookup, clamped at face edges (for precomputation, where many samples hide the seams).
glm::vec3 sample_bilinear(const FloatCube& cube, const glm::dvec3& direction);
// Half the size, each texel the mean of four.
FloatCube downsample(const FloatCube& cube);
// A cube whose texels are the mean of `supersample`² evaluations of radiance(direction) over each texel.
template <typename Radiance>
FloatCube tabulate(int size, int supersample, const Radiance& radiance);

}  // namespace fxview::lighting

#include "lighting/cube_map_tabulate.hpp"
