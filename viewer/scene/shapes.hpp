// Built-in meshes with analytic normals and tangent frames. Every shape faces the default camera
// (+Z) and fits in the cube [-1,1]^3: sphere, torus (axis Z), cube, plane (XY), disc (a CD with its
// hole; UV = planar, centre at (0.5, 0.5)) and a (2,3) torus knot as the showcase shape.
#pragma once
#include <string>
#include <string_view>
#include <vector>

#include "scene/mesh.hpp"

namespace fxview::scene {

MeshData make_sphere(float radius = 1.0f, int slices = 64, int stacks = 32);
MeshData make_torus(float major_radius = 0.7f, float minor_radius = 0.3f, int rings = 64, int sides = 32);
MeshData make_cube(float half_extent = 0.7f);
MeshData make_plane(float half_extent = 1.0f, int subdivisions = 16);
MeshData make_disc(float outer_radius = 1.0f, float inner_radius = 0.125f, int segments = 128, int rings = 8);
MeshData make_knot(int segments = 256, int sides = 24);

const std::vector<std::string>& builtin_mesh_names();
// A built-in name or the path of an OBJ file (anything ending in .obj); throws UsageError for an
// unknown name, Error for an unreadable file.
MeshData load_mesh(std::string_view name_or_path);

}  // namespace fxview::scene
