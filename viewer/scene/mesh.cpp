#include "scene/mesh.hpp"

#include <algorithm>
#include <cmath>

namespace fxview::scene {
namespace {

glm::vec3 any_perpendicular(const glm::vec3& n) {
    const glm::vec3 helper = std::abs(n.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
    return glm::normalize(glm::cross(helper, n));
}

}  // namespace

void compute_normals(MeshData& mesh) {
    std::vector<glm::vec3> sums(mesh.vertices.size(), glm::vec3(0.0f));
    for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
        const auto a = mesh.indices[i], b = mesh.indices[i + 1], c = mesh.indices[i + 2];
        // The cross product's length is twice the area: larger faces weigh more.
        const glm::vec3 face = glm::cross(mesh.vertices[b].position - mesh.vertices[a].position,
                                          mesh.vertices[c].position - mesh.vertices[a].position);
        sums[a] += face;
        sums[b] += face;
        sums[c] += face;
    }
    for (size_t v = 0; v < mesh.vertices.size(); ++v)
        mesh.vertices[v].normal = glm::length(sums[v]) > 0.0f ? glm::normalize(sums[v]) : glm::vec3(0, 0, 1);
}

void compute_tangents(MeshData& mesh) {
    std::vector<glm::vec3> tangent_sums(mesh.vertices.size(), glm::vec3(0.0f));
    std::vector<glm::vec3> bitangent_sums(mesh.vertices.size(), glm::vec3(0.0f));
    for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
        const Vertex& v0 = mesh.vertices[mesh.indices[i]];
        const Vertex& v1 = mesh.vertices[mesh.indices[i + 1]];
        const Vertex& v2 = mesh.vertices[mesh.indices[i + 2]];
        const glm::vec3 e1 = v1.position - v0.position, e2 = v2.position - v0.position;
        const glm::vec2 d1 = v1.uv - v0.uv, d2 = v2.uv - v0.uv;
        const float determinant = d1.x * d2.y - d2.x * d1.y;
        if (std::abs(determinant) < 1e-12f) continue;  // no UV area: says nothing about the frame
        const float r = 1.0f / determinant;
        const glm::vec3 t = (e1 * d2.y - e2 * d1.y) * r;
        const glm::vec3 b = (e2 * d1.x - e1 * d2.x) * r;
        for (size_t k = 0; k < 3; ++k) {
            tangent_sums[mesh.indices[i + k]] += t;
            bitangent_sums[mesh.indices[i + k]] += b;
        }
    }
    for (size_t v = 0; v < mesh.vertices.size(); ++v) {
        Vertex& vertex = mesh.vertices[v];
        const glm::vec3 n = vertex.normal;
        glm::vec3 t = tangent_sums[v] - n * glm::dot(n, tangent_sums[v]);
        if (glm::length(t) < 1e-8f) {
            vertex.tangent = any_perpendicular(n);
            vertex.bitangent = glm::cross(n, vertex.tangent);
            continue;
        }
        vertex.tangent = glm::normalize(t);
        // Keep the UV handedness: mirrored UVs give a bitangent of -N x T.
        const float handedness = glm::dot(glm::cross(n, vertex.tangent), bitangent_sums[v]) < 0.0f ? -1.0f : 1.0f;
        vertex.bitangent = handedness * glm::cross(n, vertex.tangent);
    }
}

void fit_unit_sphere(MeshData& mesh) {
    if (mesh.vertices.empty()) return;
    glm::vec3 low(INFINITY), high(-INFINITY);
    for (const auto& v : mesh.vertices) {
        low = glm::min(low, v.position);
        high = glm::max(high, v.position);
    }
    const glm::vec3 centre = 0.5f * (low + high);
    float radius = 0.0f;
    for (const auto& v : mesh.vertices) radius = std::max(radius, glm::length(v.position - centre));
    const float scale = radius > 0.0f ? 1.0f / radius : 1.0f;
    for (auto& v : mesh.vertices) v.position = (v.position - centre) * scale;
}

}  // namespace fxview::scene
