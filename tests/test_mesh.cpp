// Built-in meshes and OBJ loading: valid indices, unit normals, orthonormal right-handed tangent
// frames, outward winding, size within [-1,1]^3; OBJ files without normals get computed ones.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>

#include "core/error.hpp"
#include "scene/obj_loader.hpp"
#include "scene/shapes.hpp"

using namespace fxview::scene;

namespace {

std::string write_temp(const std::string& name, const std::string& text) {
    std::filesystem::create_directories(FXVIEW_TEST_TMP);
    const std::string path = std::string(FXVIEW_TEST_TMP) + "/" + name;
    std::ofstream(path) << text;
    return path;
}

// Frames come from float trigonometry or finite differences (the knot): 1e-3 bounds those errors.
constexpr float kFrameTolerance = 1e-3f;

void check_mesh(const MeshData& mesh, bool right_handed_frames) {
    CAPTURE(mesh.name);
    REQUIRE(!mesh.vertices.empty());
    REQUIRE(mesh.indices.size() % 3 == 0);
    for (auto index : mesh.indices) REQUIRE(index < mesh.vertices.size());
    int frame_errors = 0, outside = 0;
    for (const auto& v : mesh.vertices) {
        if (glm::any(glm::greaterThan(glm::abs(v.position), glm::vec3(1.0f + 1e-5f)))) ++outside;
        const bool unit = std::abs(glm::length(v.normal) - 1) < kFrameTolerance &&
                          std::abs(glm::length(v.tangent) - 1) < kFrameTolerance &&
                          std::abs(glm::length(v.bitangent) - 1) < kFrameTolerance;
        const bool orthogonal = std::abs(glm::dot(v.normal, v.tangent)) < kFrameTolerance &&
                                std::abs(glm::dot(v.normal, v.bitangent)) < kFrameTolerance;
        const bool handed = !right_handed_frames || glm::dot(glm::cross(v.tangent, v.bitangent), v.normal) > 0.99f;
        if (!(unit && orthogonal && handed)) ++frame_errors;
    }
    CHECK(frame_errors == 0);
    CHECK(outside == 0);  // fits in the cube [-1,1]^3
    // Counter-clockwise from outside: the face normal agrees with the vertex normals.
    int inward = 0, faces = 0;
    for (size_t i = 0; i < mesh.indices.size(); i += 3) {
        const Vertex& a = mesh.vertices[mesh.indices[i]];
        const Vertex& b = mesh.vertices[mesh.indices[i + 1]];
        const Vertex& c = mesh.vertices[mesh.indices[i + 2]];
        const glm::vec3 face = glm::cross(b.position - a.position, c.position - a.position);
        if (glm::length(face) < 1e-9f) continue;  // degenerate pole triangles say nothing
        ++faces;
        if (glm::dot(face, a.normal + b.normal + c.normal) <= 0.0f) ++inward;
    }
    CHECK(faces > 0);
    CHECK(inward == 0);
}

}  // namespace

TEST_CASE("every built-in mesh is well formed") {
    for (const auto& name : builtin_mesh_names()) check_mesh(load_mesh(name), true);
}

TEST_CASE("sphere: analytic normal equals position, u = 0.5 faces the camera") {
    const MeshData sphere = make_sphere(1.0f, 16, 8);
    for (const auto& v : sphere.vertices) CHECK(glm::length(v.normal - v.position) < 1e-5f);
    bool found_front = false;
    for (const auto& v : sphere.vertices)
        if (std::abs(v.uv.x - 0.5f) < 1e-6f && std::abs(v.uv.y - 0.5f) < 1e-6f) {
            found_front = true;
            CHECK(v.normal.z == doctest::Approx(1.0f));
            CHECK(v.tangent.x == doctest::Approx(1.0f));
            CHECK(v.bitangent.y == doctest::Approx(1.0f));
        }
    CHECK(found_front);
}

TEST_CASE("disc: planar UVs centred at (0.5, 0.5) with the CD's hole") {
    const MeshData disc = make_disc();
    float smallest_radius = 10.0f;
    for (const auto& v : disc.vertices) {
        smallest_radius = std::min(smallest_radius, glm::length(v.position));
        CHECK(glm::length(v.uv - glm::vec2(0.5f) - glm::vec2(v.position) * 0.5f) < 1e-6f);
    }
    CHECK(smallest_radius == doctest::Approx(0.125f));  // 15 mm hole in a 120 mm disc
}

TEST_CASE("OBJ without normals: normals, tangents and size are computed") {
    // A square facing +Y, 10 units away and 4 units wide; u grows towards -X, v towards +Z.
    const std::string path = write_temp("quad.obj",
                                        "v 8 10 8\nv 12 10 8\nv 12 10 12\nv 8 10 12\n"
                                        "vt 1 0\nvt 0 0\nvt 0 1\nvt 1 1\n"
                                        "f 1/1 4/4 3/3\nf 1/1 3/3 2/2\n");
    const MeshData mesh = load_obj(path);
    CHECK(mesh.vertices.size() == 4);
    CHECK(mesh.indices.size() == 6);
    for (const auto& v : mesh.vertices) {
        CHECK(v.normal.y == doctest::Approx(1.0f));  // counter-clockwise seen from +Y
        CHECK(glm::length(v.position) == doctest::Approx(1.0f));  // centred, corners on the unit sphere
        CHECK(std::abs(glm::dot(v.tangent, v.normal)) < 1e-5f);
        CHECK(v.tangent.x == doctest::Approx(-1.0f));
        CHECK(v.bitangent.z == doctest::Approx(1.0f));
    }
    check_mesh(mesh, true);
}

TEST_CASE("OBJ errors name the file") {
    CHECK_THROWS_WITH_AS(load_obj(std::string(FXVIEW_TEST_TMP) + "/missing.obj"), doctest::Contains("missing.obj"),
                         fxview::Error);
    const std::string empty = write_temp("empty.obj", "# nothing here\nv 0 0 0\n");
    CHECK_THROWS_WITH_AS(load_obj(empty), doctest::Contains("empty.obj: OBJ holds no faces"), fxview::Error);
    const std::string dangling = write_temp("dangling.obj", "v 0 0 0\nv 1 0 0\nf 1 2 7\n");
    CHECK_THROWS_WITH_AS(load_obj(dangling), doctest::Contains("dangling.obj"), fxview::Error);
    CHECK_THROWS_AS(load_mesh("teapot-that-is-not-there"), fxview::UsageError);
}
