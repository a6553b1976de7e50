#include "render/gpu_mesh.hpp"

#include <cstddef>

namespace fxview::render {

GpuMesh::GpuMesh(const scene::MeshData& mesh)
    : vertices_(gl::create_buffer()),
      indices_(gl::create_buffer()),
      vertex_array_(gl::create_vertex_array()),
      index_count_(static_cast<GLsizei>(mesh.indices.size())) {
    using scene::Vertex;
    glNamedBufferStorage(vertices_.get(), static_cast<GLsizeiptr>(mesh.vertices.size() * sizeof(Vertex)),
                         mesh.vertices.data(), 0);
    glNamedBufferStorage(indices_.get(), static_cast<GLsizeiptr>(mesh.indices.size() * sizeof(std::uint32_t)),
                         mesh.indices.data(), 0);
    const GLuint vao = vertex_array_.get();
    glVertexArrayVertexBuffer(vao, 0, vertices_.get(), 0, sizeof(Vertex));
    glVertexArrayElementBuffer(vao, indices_.get());
    struct Attribute {
        GLint components;
        size_t offset;
    };
    const Attribute attributes[] = {{3, offsetof(Vertex, position)},
                                    {3, offsetof(Vertex, normal)},
                                    {3, offsetof(Vertex, tangent)},
                                    {3, offsetof(Vertex, bitangent)},
                                    {2, offsetof(Vertex, uv)}};
    for (GLuint location = 0; location < 5; ++location) {
        glEnableVertexArrayAttrib(vao, location);
        glVertexArrayAttribFormat(vao, location, attributes[location].components, GL_FLOAT, GL_FALSE,
                                  static_cast<GLuint>(attributes[location].offset));
        glVertexArrayAttribBinding(vao, location, 0);
    }
}

void GpuMesh::draw() const {
    glBindVertexArray(vertex_array_.get());
    glDrawElements(GL_TRIANGLES, index_count_, GL_UNSIGNED_INT, nullptr);
    glBindVertexArray(0);
}

}  // namespace fxview::render
