#include "scene/shapes.hpp"

#include <glm/gtc/constants.hpp>

#include <cmath>
#include <functional>

#include "core/error.hpp"
#include "scene/obj_loader.hpp"

namespace fxview::scene {
namespace {

constexpr float kPi = glm::pi<float>();

// Vertices on a (columns+1) x (rows+1) grid of parameters s, t in [0,1]; triangles are wound so
// that d/ds x d/dt points out of the surface.
MeshData make_grid(std::string name, int columns, int rows, const std::function<Vertex(float s, float t)>& at) {
    MeshData mesh;
    mesh.name = std::move(name);
    for (int j = 0; j <= rows; ++j)
        for (int i = 0; i <= columns; ++i)
            mesh.vertices.push_back(at(static_cast<float>(i) / columns, static_cast<float>(j) / rows));
    const auto index = [columns](int i, int j) { return static_cast<std::uint32_t>(j * (columns + 1) + i); };
    for (int j = 0; j < rows; ++j)
        for (int i = 0; i < columns; ++i) {
            mesh.indices.insert(mesh.indices.end(), {index(i, j), index(i + 1, j), index(i + 1, j + 1)});
            mesh.indices.insert(mesh.indices.end(), {index(i, j), index(i + 1, j + 1), index(i, j + 1)});
        }
    return mesh;
}

}  // namespace

MeshData make_sphere(float radius, int slices, int stacks) {
    // u = 0.5 faces +Z, the seam is at the back; v = 1 at the north pole (+Y).
    return make_grid("sphere", slices, stacks, [radius](float u, float v) {
        const float phi = 2.0f * kPi * (u - 0.5f);
        const float theta = kPi * (1.0f - v);
        const glm::vec3 n(std::sin(theta) * std::sin(phi), std::cos(theta), std::sin(theta) * std::cos(phi));
        Vertex vertex;
        vertex.position = radius * n;
        vertex.normal = n;
        vertex.tangent = glm::vec3(std::cos(phi), 0.0f, -std::sin(phi));
        vertex.bitangent = glm::cross(n, vertex.tangent);
        vertex.uv = {u, v};
        return vertex;
    });
}

MeshData make_torus(float major_radius, float minor_radius, int rings, int sides) {
    return make_grid("torus", rings, sides, [=](float u, float v) {
        const float a = 2.0f * kPi * u, b = 2.0f * kPi * v;
        Vertex vertex;
        vertex.normal = {std::cos(b) * std::cos(a), std::cos(b) * std::sin(a), std::sin(b)};
        vertex.position = glm::vec3(major_radius * std::cos(a), major_radius * std::sin(a), 0.0f) +
                          minor_radius * vertex.normal;
        vertex.tangent = {-std::sin(a), std::cos(a), 0.0f};
        vertex.bitangent = {-std::sin(b) * std::cos(a), -std::sin(b) * std::sin(a), std::cos(b)};
        vertex.uv = {u, v};
        return vertex;
    });
}

MeshData make_cube(float half_extent) {
    struct Face {
        glm::vec3 normal, tangent;
    };
    const Face faces[] = {{{1, 0, 0}, {0, 0, -1}}, {{-1, 0, 0}, {0, 0, 1}}, {{0, 1, 0}, {1, 0, 0}},
                          {{0, -1, 0}, {1, 0, 0}}, {{0, 0, 1}, {1, 0, 0}},  {{0, 0, -1}, {-1, 0, 0}}};
    MeshData mesh;
    mesh.name = "cube";
    for (const Face& face : faces) {
        const glm::vec3 bitangent = glm::cross(face.normal, face.tangent);
        const auto first = static_cast<std::uint32_t>(mesh.vertices.size());
        for (const glm::vec2 corner : {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(1, 1), glm::vec2(-1, 1)}) {
            Vertex vertex;
            vertex.position = half_extent * (face.normal + corner.x * face.tangent + corner.y * bitangent);
            vertex.normal = face.normal;
            vertex.tangent = face.tangent;
            vertex.bitangent = bitangent;
            vertex.uv = corner * 0.5f + 0.5f;
            mesh.vertices.push_back(vertex);
        }
        mesh.indices.insert(mesh.indices.end(), {first, first + 1, first + 2, first, first + 2, first + 3});
    }
    return mesh;
}

MeshData make_plane(float half_extent, int subdivisions) {
    return make_grid("plane", subdivisions, subdivisions, [half_extent](float u, float v) {
        Vertex vertex;
        vertex.position = {(2.0f * u - 1.0f) * half_extent, (2.0f * v - 1.0f) * half_extent, 0.0f};
        vertex.uv = {u, v};
        return vertex;  // normal +Z, tangent +X, bitangent +Y are the defaults
    });
}

MeshData make_disc(float outer_radius, float inner_radius, int segments, int rings) {
    // s runs outwards, t around: d/ds x d/dt = +Z. UVs are planar so that the centre is (0.5, 0.5).
    return make_grid("disc", rings, segments, [=](float s, float t) {
        const float radius = inner_radius + s * (outer_radius - inner_radius);
        const float angle = 2.0f * kPi * t;
        Vertex vertex;
        vertex.position = {radius * std::cos(angle), radius * std::sin(angle), 0.0f};
        vertex.uv = glm::vec2(vertex.position) / (2.0f * outer_radius) + 0.5f;
        return vertex;
    });
}

MeshData make_knot(int segments, int sides) {
    // (2,3) torus knot, scaled into the unit sphere, with a tube around its Frenet frame.
    constexpr float kScale = 0.28f, kTube = 0.14f;
    const auto curve = [](float t) {
        return kScale * glm::vec3((2.0f + std::cos(3 * t)) * std::cos(2 * t), (2.0f + std::cos(3 * t)) * std::sin(2 * t),
                                  std::sin(3 * t));
    };
    return make_grid("knot", segments, sides, [&](float u, float v) {
        const float t = 2.0f * kPi * u, h = 1e-3f;
        const glm::vec3 first = (curve(t + h) - curve(t - h)) / (2 * h);
        const glm::vec3 second = (curve(t + h) - 2.0f * curve(t) + curve(t - h)) / (h * h);
        const glm::vec3 tangent = glm::normalize(first);
        const glm::vec3 principal = glm::normalize(second - glm::dot(second, tangent) * tangent);
        const glm::vec3 binormal = glm::cross(tangent, principal);
        const float b = 2.0f * kPi * v;
        Vertex vertex;
        vertex.normal = std::cos(b) * principal - std::sin(b) * binormal;
        vertex.position = curve(t) + kTube * vertex.normal;
        vertex.tangent = tangent;
        vertex.bitangent = -std::sin(b) * principal - std::cos(b) * binormal;
        vertex.uv = {u, v};
        return vertex;
    });
}

const std::vector<std::string>& builtin_mesh_names() {
    static const std::vector<std::string> names = {"sphere", "torus", "cube", "plane", "disc", "knot"};
    return names;
}

MeshData load_mesh(std::string_view name_or_path) {
    if (name_or_path == "sphere") return make_sphere();
    if (name_or_path == "torus") return make_torus();
    if (name_or_path == "cube") return make_cube();
    if (name_or_path == "plane") return make_plane();
    if (name_or_path == "disc") return make_disc();
    if (name_or_path == "knot") return make_knot();
    if (name_or_path.size() > 4) {
        std::string extension(name_or_path.substr(name_or_path.size() - 4));
        for (auto& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        if (extension == ".obj") return load_obj(std::string(name_or_path));
    }
    std::string known;
    for (const auto& name : builtin_mesh_names()) known += (known.empty() ? "" : ", ") + name;
    throw UsageError("unknown mesh '" + std::string(name_or_path) + "' (built-in: " + known + ", or a .obj file)");
}

}  // namespace fxview::scene
