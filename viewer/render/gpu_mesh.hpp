// A mesh uploaded to the GPU: vertex buffer, index buffer and the vertex array that describes them
// (attribute locations 0-4: position, normal, tangent, bitangent, uv).
#pragma once
#include "gl/objects.hpp"
#include "scene/mesh.hpp"

namespace fxview::render {

class GpuMesh {
public:
    explicit GpuMesh(const scene::MeshData& mesh);
    void draw() const;
    GLsizei index_count() const { return index_count_; }

private:
    gl::Buffer vertices_;
    gl::Buffer indices_;
    gl::VertexArray vertex_array_;
    GLsizei index_count_ = 0;
};

}  // namespace fxview::render
