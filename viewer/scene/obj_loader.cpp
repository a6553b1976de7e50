#include "scene/obj_loader.hpp"

#include <tiny_obj_loader.h>

#include <filesystem>
#include <map>
#include <tuple>

#include "core/error.hpp"

namespace fxview::scene {

MeshData load_obj(const std::string& path) {
    if (!std::filesystem::is_regular_file(path)) throw Error(path + ": no such OBJ file");
    tinyobj::ObjReaderConfig config;
    config.triangulate = true;
    config.vertex_color = false;
    config.mtl_search_path = std::filesystem::path(path).parent_path().string();
    tinyobj::ObjReader reader;
    if (!reader.ParseFromFile(path, config)) {
        std::string message = reader.Error();
        while (!message.empty() && message.back() == '\n') message.pop_back();
        throw Error(path + ": cannot read OBJ: " + (message.empty() ? "parse error" : message));
    }
    const auto& attributes = reader.GetAttrib();
    MeshData mesh;
    mesh.name = std::filesystem::path(path).filename().string();
    bool has_normals = true, has_uvs = true;
    std::map<std::tuple<int, int, int>, std::uint32_t> known;
    for (const auto& shape : reader.GetShapes()) {
        for (const auto& index : shape.mesh.indices) {
            const auto key = std::make_tuple(index.vertex_index, index.texcoord_index, index.normal_index);
            if (auto found = known.find(key); found != known.end()) {
                mesh.indices.push_back(found->second);
                continue;
            }
            if (index.vertex_index < 0 || 3 * static_cast<size_t>(index.vertex_index) + 2 >= attributes.vertices.size())
                throw Error(path + ": face refers to a missing vertex");
            Vertex vertex;
            const size_t p = 3 * static_cast<size_t>(index.vertex_index);
            vertex.position = {attributes.vertices[p], attributes.vertices[p + 1], attributes.vertices[p + 2]};
            if (index.normal_index >= 0) {
                const size_t n = 3 * static_cast<size_t>(index.normal_index);
                vertex.normal = glm::normalize(
                    glm::vec3(attributes.normals[n], attributes.normals[n + 1], attributes.normals[n + 2]));
            } else {
                has_normals = false;
            }
            if (index.texcoord_index >= 0) {
                const size_t t = 2 * static_cast<size_t>(index.texcoord_index);
                vertex.uv = {attributes.texcoords[t], attributes.texcoords[t + 1]};
            } else {
                has_uvs = false;
            }
            const auto id = static_cast<std::uint32_t>(mesh.vertices.size());
            known.emplace(key, id);
            mesh.vertices.push_back(vertex);
            mesh.indices.push_back(id);
        }
    }
    if (mesh.indices.empty()) throw Error(path + ": OBJ holds no faces");
    if (!has_normals) compute_normals(mesh);
    if (!has_uvs)
        for (auto& vertex : mesh.vertices) vertex.uv = glm::vec2(0.0f);  // compute_tangents then picks any frame
    compute_tangents(mesh);
    fit_unit_sphere(mesh);
    return mesh;
}

}  // namespace fxview::scene
