// Meshes by name (built-in or OBJ path), uploaded on first use and kept for later frames.
#pragma once
#include <map>
#include <string>

#include "render/gpu_mesh.hpp"

namespace fxview::render {

class MeshCache {
public:
    const GpuMesh& get(const std::string& name_or_path);

private:
    std::map<std::string, GpuMesh> meshes_;
};

}  // namespace fxview::render
