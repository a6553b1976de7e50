// The irradiance of a cube of radiance (or of any quantity linear in it, such as the weights of a
// spectral form), as a cube: E(n) / π per texel, what a white Lambertian surface facing n reflects.
// By direct summation over the texels, not spherical harmonics: order-2 harmonics ring about a small
// bright source drawn into the cube (the sun) and go negative behind it.
#pragma once
#include "lighting/cube_map.hpp"

namespace fxview::lighting {

// `size` texels across each face of the result; the source is first box-averaged to at most
// `source_size` (energy is kept: a 1.5° sun moves by at most half a source texel, 0.7° at 64).
FloatCube cosine_convolved(const FloatCube& radiance, int size = 32, int source_size = 64);

}  // namespace fxview::lighting
