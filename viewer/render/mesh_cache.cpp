#include "render/mesh_cache.hpp"

#include "scene/shapes.hpp"

namespace fxview::render {

const GpuMesh& MeshCache::get(const std::string& name_or_path) {
    auto found = meshes_.find(name_or_path);
    if (found == meshes_.end()) found = meshes_.emplace(name_or_path, GpuMesh(scene::load_mesh(name_or_path))).first;
    return found->second;
}

}  // namespace fxview::render
