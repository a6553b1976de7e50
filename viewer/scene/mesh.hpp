// Triangle meshes as the renderer and the CPU references see them: every vertex carries a full
// tangent frame (T, B, N with T x B = N for right-handed UVs) and one texture coordinate.
#pragma once
#include <glm/glm.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace fxview::scene {

struct Vertex {
    glm::vec3 position{0.0f};
    glm::vec3 normal{0.0f, 0.0f, 1.0f};
    glm::vec3 tangent{1.0f, 0.0f, 0.0f};    // direction of increasing u
    glm::vec3 bitangent{0.0f, 1.0f, 0.0f};  // direction of increasing v
    glm::vec2 uv{0.0f};
};

struct MeshData {
    std::string name;
    std::vector<Vertex> vertices;
    std::vector<std::uint32_t> indices;  // triangles, counter-clockwise seen from outside
};

// Area-weighted vertex normals from the triangles (for meshes that come without normals).
void compute_normals(MeshData& mesh);
// Per-vertex tangent and bitangent from the UV layout (Lengyel), orthogonalised against the normal;
// meshes without a usable UV layout get an arbitrary orthonormal frame around the normal.
void compute_tangents(MeshData& mesh);
// Moves the mesh's bounding-box centre to the origin and scales it into the unit sphere.
void fit_unit_sphere(MeshData& mesh);

}  // namespace fxview::scene
