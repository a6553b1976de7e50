// Wavefront OBJ through tinyobjloader: triangulated, vertices de-duplicated per (position, uv,
// normal) triple, missing normals and tangents computed, scaled into the unit sphere.
#pragma once
#include "core/limits.hpp"
#include <string>

#include "scene/mesh.hpp"

namespace fxview::scene {

MeshData load_obj(const std::string& path, const ResourceLimits& limits = {});  // throws fxview::Error naming the file

}  // namespace fxview::scene
