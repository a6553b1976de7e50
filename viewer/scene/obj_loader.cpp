#include "scene/obj_loader.hpp"

#include <tiny_obj_loader.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string_view>
#include <map>
#include <tuple>

#include "core/error.hpp"
#include "core/limits.hpp"
#include "core/text.hpp"

namespace fxview::scene {

namespace {

std::string_view next_word(std::string_view line, size_t& i) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
    const size_t begin = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r') ++i;
    return line.substr(begin, i - begin);
}

// tinyobjloader trusts the indices of `f` lines and the numbers of `v`/`vn`/`vt` lines; a face
// naming a normal that no `vn` line defines made it read out of bounds. This pass checks every
// reference and number first, so that each problem is reported with its line.
// tinyobjloader needs ~200 bytes per triangle and triangulates a polygon in quadratic time: both
// are bounded before it runs (documented in docs/effect-format.md, "Budgets").
constexpr std::int64_t kMaxTriangles = 2000000;
constexpr std::int64_t kMaxPolygonCorners = 1024;

void validate_obj(const std::string& path, const std::string& text) {
    std::int64_t counts[3] = {0, 0, 0};  // v, vt, vn: totals, for references to later lines
    std::int64_t triangles = 0;
    for (size_t pass = 0; pass < 2; ++pass) {
        std::int64_t seen[3] = {0, 0, 0};
        size_t start = 0;
        for (int number = 1; start < text.size(); ++number) {
            size_t end = text.find('\n', start);
            if (end == std::string::npos) end = text.size();
            const std::string_view line(text.data() + start, end - start);
            start = end + 1;
            size_t i = 0;
            const std::string_view keyword = next_word(line, i);
            const auto where = [&] { return path + ":" + std::to_string(number) + ": "; };
            const int kind = keyword == "v" ? 0 : keyword == "vt" ? 1 : keyword == "vn" ? 2 : -1;
            if (kind >= 0) {
                ++seen[kind];
                if (pass == 1) continue;
                int numbers = 0;
                for (std::string_view word = next_word(line, i); !word.empty(); word = next_word(line, i)) {
                    ++numbers;
                    double value = 0;
                    const auto [stop, error] = std::from_chars(word.data(), word.data() + word.size(), value);
                    if (error != std::errc() || stop != word.data() + word.size() || !std::isfinite(value))
                        throw Error(where() + "'" + excerpt(word) + "' is not a finite number");
                }
                if (numbers < (kind == 1 ? 1 : 3)) throw Error(where() + "'" + std::string(keyword) + "' needs " + (kind == 1 ? "u v" : "x y z"));
                continue;
            }
            if (keyword != "f" || pass == 0) continue;
            std::int64_t corners = 0;
            for (std::string_view corner = next_word(line, i); !corner.empty(); corner = next_word(line, i)) {
                if (++corners > kMaxPolygonCorners)
                    throw Error(where() + "a face with more than " + std::to_string(kMaxPolygonCorners) + " corners");
                size_t part = 0;
                for (size_t from = 0; from <= corner.size() && part < 3; ++part) {
                    size_t slash = corner.find('/', from);
                    if (slash == std::string_view::npos) slash = corner.size();
                    const std::string_view index_text = corner.substr(from, slash - from);
                    from = slash + 1;
                    if (index_text.empty()) {
                        if (part == 0) throw Error(where() + "a face corner needs a vertex index");
                        continue;
                    }
                    std::int64_t index = 0;
                    const auto [stop, error] = std::from_chars(index_text.data(), index_text.data() + index_text.size(), index);
                    static const char* const names[3] = {"vertex", "texture coordinate", "normal"};
                    if (error != std::errc() || stop != index_text.data() + index_text.size() || index == 0)
                        throw Error(where() + "'" + excerpt(corner) + "' is not a valid face corner");
                    // Negative indices count back from the last line of that kind read so far.
                    const std::int64_t resolved = index > 0 ? index : seen[part] + 1 + index;
                    if (resolved < 1 || resolved > (index > 0 ? counts[part] : seen[part]))
                        throw Error(where() + "face refers to " + names[part] + " " + std::to_string(index) + ", but the file defines " +
                                    std::to_string(counts[part]));
                    if (slash == corner.size()) break;
                }
                if (part > 3 || std::count(corner.begin(), corner.end(), '/') > 2)
                    throw Error(where() + "'" + excerpt(corner) + "' is not a valid face corner");
            }
            if (corners < 3) throw Error(where() + "a face needs at least three corners");
            triangles += corners - 2;
            if (triangles > kMaxTriangles)
                throw Error(where() + "the mesh exceeds " + std::to_string(kMaxTriangles) + " triangles");
        }
        std::copy(seen, seen + 3, counts);
    }
}

}  // namespace

MeshData load_obj(const std::string& path, const ResourceLimits& limits) {
    std::error_code error;
    if (!std::filesystem::is_regular_file(path, error)) throw Error(path + ": no such OBJ file");
    checked_file_size(path, limits);
    std::ifstream file(path, std::ios::binary);
    std::string text((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
    if (text.rfind("\xEF\xBB\xBF", 0) == 0) text.erase(0, 3);  // a UTF-8 byte order mark is no content
    if (!file && !file.eof()) throw Error(path + ": cannot read OBJ");
    validate_obj(path, text);
    tinyobj::attrib_t attributes;
    std::vector<tinyobj::shape_t> shapes;
    std::vector<tinyobj::material_t> materials;
    std::string warnings, message;
    std::istringstream stream(text);
    // No material reader: `mtllib` lines are ignored, so an OBJ cannot make fxview open other files.
    if (!tinyobj::LoadObj(&attributes, &shapes, &materials, &warnings, &message, &stream, nullptr, true)) {
        while (!message.empty() && message.back() == '\n') message.pop_back();
        throw Error(path + ": cannot read OBJ: " + (message.empty() ? "parse error" : excerpt(message, 200)));
    }
    MeshData mesh;
    mesh.name = std::filesystem::path(path).filename().string();
    bool has_normals = true, has_uvs = true;
    std::map<std::tuple<int, int, int>, std::uint32_t> known;
    const auto within = [](int index, size_t components, const std::vector<tinyobj::real_t>& data) {
        return index >= 0 && components * static_cast<size_t>(index) + components <= data.size();
    };
    for (const auto& shape : shapes) {
        for (const auto& index : shape.mesh.indices) {
            const auto key = std::make_tuple(index.vertex_index, index.texcoord_index, index.normal_index);
            if (auto found = known.find(key); found != known.end()) {
                mesh.indices.push_back(found->second);
                continue;
            }
            if (!within(index.vertex_index, 3, attributes.vertices)) throw Error(path + ": face refers to a missing vertex");
            Vertex vertex;
            const size_t p = 3 * static_cast<size_t>(index.vertex_index);
            vertex.position = {attributes.vertices[p], attributes.vertices[p + 1], attributes.vertices[p + 2]};
            const size_t n = 3 * static_cast<size_t>(std::max(0, index.normal_index));
            const glm::vec3 normal = within(index.normal_index, 3, attributes.normals)
                                         ? glm::vec3(attributes.normals[n], attributes.normals[n + 1], attributes.normals[n + 2])
                                         : glm::vec3(0.0f);
            if (glm::dot(normal, normal) > 0.0f) vertex.normal = glm::normalize(normal);
            else has_normals = false;  // missing or zero-length normals: computed from the faces
            if (within(index.texcoord_index, 2, attributes.texcoords)) {
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
