// The CPU references shade from the captured G-buffer, so a wrong capture (position, normal, which
// surface is in front) would fool shader and reference alike. Checked here for every built-in shape
// against a CPU ray cast of the exact surface it approximates: a signed distance function traced
// from the camera, independent of the mesh and of GL.
//
// The tolerances come from the tessellation itself: each mesh's flat facets deviate from the exact
// surface by their sag, and their interpolated normals from the exact normals by an angle; both are
// measured on the CPU mesh at 91 sample points of every triangle, with a margin for the points between.
#include <doctest/doctest.h>

#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <numbers>

#include "app/effect_options.hpp"
#include "gl/render_target.hpp"
#include "math/transform.hpp"
#include "render/effect_session.hpp"
#include "scene/scene.hpp"
#include "scene/shapes.hpp"
#include "pixel_rays.hpp"
#include "test_support.hpp"

using namespace fxview;

namespace {

// An exact shape: its distance function (the distance to the surface, negative inside for closed
// shapes) and its normal at a point on or near the surface.
struct ExactShape {
    std::function<double(glm::dvec3)> distance;
    std::function<glm::dvec3(glm::dvec3)> normal;
    // The distance of a point of a facet whose texture coordinate u is known (faster for the knot).
    std::function<double(glm::dvec3, double u)> facet_distance = nullptr;
};

double box_distance(glm::dvec3 p, glm::dvec3 half) {
    const glm::dvec3 d = glm::abs(p) - half;
    return glm::length(glm::max(d, 0.0)) + std::min(std::max(d.x, std::max(d.y, d.z)), 0.0);
}

// The knot's centre line, as scene/shapes.cpp defines it (scale 0.28, tube 0.14).
glm::dvec3 knot_curve(double t) {
    return 0.28 * glm::dvec3((2.0 + std::cos(3 * t)) * std::cos(2 * t), (2.0 + std::cos(3 * t)) * std::sin(2 * t), std::sin(3 * t));
}

// The point of the knot's centre line nearest to p, by golden-section search for t in [from, to].
glm::dvec3 nearest_on_knot(glm::dvec3 p, double from, double to) {
    const double ratio = (std::sqrt(5.0) - 1.0) / 2.0;
    for (int i = 0; i < 50; ++i) {
        const double c = to - ratio * (to - from), d = from + ratio * (to - from);
        if (glm::length(knot_curve(c) - p) < glm::length(knot_curve(d) - p)) to = d;
        else from = c;
    }
    return knot_curve(0.5 * (from + to));
}

// Anywhere: the best of 512 samples, then refined between its neighbours. The strands stay more than
// two tube radii apart, so within a tube radius of the knot the best sample lies in the right valley.
glm::dvec3 nearest_on_knot(glm::dvec3 p) {
    constexpr int kSamples = 512;
    const double step = 2.0 * std::numbers::pi / kSamples;
    double best_t = 0, best = 1e300;
    for (int i = 0; i < kSamples; ++i) {
        const double d = glm::length(knot_curve(i * step) - p);
        if (d < best) {
            best = d;
            best_t = i * step;
        }
    }
    return nearest_on_knot(p, best_t - step, best_t + step);
}

ExactShape exact_shape(const std::string& name) {
    constexpr glm::dvec3 kUp(0, 0, 1);
    if (name == "sphere") return {[](glm::dvec3 p) { return glm::length(p) - 1.0; }, [](glm::dvec3 p) { return glm::normalize(p); }};
    if (name == "torus") {
        const auto ring_point = [](glm::dvec3 p) { return 0.7 * glm::normalize(glm::dvec3(p.x, p.y, 0)); };
        return {[ring_point](glm::dvec3 p) { return glm::length(p - ring_point(p)) - 0.3; },
                [ring_point](glm::dvec3 p) { return glm::normalize(p - ring_point(p)); }};
    }
    if (name == "cube")
        return {[](glm::dvec3 p) { return box_distance(p, glm::dvec3(0.7)); },
                [](glm::dvec3 p) {
                    const glm::dvec3 a = glm::abs(p);  // the face whose axis the point is farthest along
                    const int axis = a.x >= a.y && a.x >= a.z ? 0 : a.y >= a.z ? 1 : 2;
                    glm::dvec3 n(0.0);
                    n[axis] = p[axis] > 0 ? 1.0 : -1.0;
                    return n;
                }};
    if (name == "plane") return {[](glm::dvec3 p) { return box_distance(p, glm::dvec3(1, 1, 0)); }, [kUp](glm::dvec3) { return kUp; }};
    if (name == "disc")  // the annulus 0.125 <= r <= 1 in z = 0
        return {[](glm::dvec3 p) {
                    const double radial = std::max(std::abs(std::hypot(p.x, p.y) - 0.5625) - 0.4375, 0.0);
                    return std::hypot(radial, p.z);
                },
                [kUp](glm::dvec3) { return kUp; }};
    if (name == "knot") {
        const double facet = 2.0 * std::numbers::pi / 256;  // the mesh's segments along the curve
        return {[](glm::dvec3 p) { return glm::length(p - nearest_on_knot(p)) - 0.14; },
                [](glm::dvec3 p) { return glm::normalize(p - nearest_on_knot(p)); },
                [facet](glm::dvec3 p, double u) {
                    const double t = 2.0 * std::numbers::pi * u;
                    return glm::length(p - nearest_on_knot(p, t - 2 * facet, t + 2 * facet)) - 0.14;
                }};
    }
    FAIL("no exact shape for ", name);
    return {};
}

struct TessellationBounds {
    double sag = 0;           // largest distance of a facet point from the exact surface
    double normal_angle = 0;  // largest angle between an interpolated and the exact normal
};

TessellationBounds tessellation_bounds(const scene::MeshData& mesh, const ExactShape& shape) {
    // Barycentric points i/12, j/12, k/12 of every triangle: all of them for the sag; the interior
    // ones (none zero) for the normal, which is exact at the vertices and ambiguous on a cube's edges.
    constexpr int kDivisions = 12;
    TessellationBounds bounds;
    for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const scene::Vertex& a = mesh.vertices[mesh.indices[t]];
        const scene::Vertex& b = mesh.vertices[mesh.indices[t + 1]];
        const scene::Vertex& c = mesh.vertices[mesh.indices[t + 2]];
        for (int i = 0; i <= kDivisions; ++i)
            for (int j = 0; i + j <= kDivisions; ++j) {
                const int k = kDivisions - i - j;
                const glm::dvec3 w = glm::dvec3(i, j, k) / static_cast<double>(kDivisions);
                const glm::dvec3 p = w.x * glm::dvec3(a.position) + w.y * glm::dvec3(b.position) + w.z * glm::dvec3(c.position);
                const double u = w.x * a.uv.x + w.y * b.uv.x + w.z * c.uv.x;
                bounds.sag = std::max(bounds.sag, std::abs(shape.facet_distance ? shape.facet_distance(p, u) : shape.distance(p)));
                if (i == 0 || j == 0 || k == 0) continue;
                const glm::dvec3 n = glm::normalize(w.x * glm::dvec3(a.normal) + w.y * glm::dvec3(b.normal) + w.z * glm::dvec3(c.normal));
                bounds.normal_angle = std::max(bounds.normal_angle, std::acos(std::clamp(glm::dot(n, shape.normal(p)), -1.0, 1.0)));
            }
    }
    // The deviations are smooth over a facet: a tenth (sag) and a fifth (normal, whose samples stop
    // 1/12 short of the edges) more covers the points between the samples.
    bounds.sag *= 1.1;
    bounds.normal_angle *= 1.2;
    return bounds;
}

// Sphere tracing along the ray: the distance to the first hit, or a negative value for a miss.
double trace(const ExactShape& shape, glm::dvec3 origin, glm::dvec3 direction) {
    double t = 0;
    for (int i = 0; i < 20000 && t < 10.0; ++i) {
        const double d = shape.distance(origin + t * direction);
        if (d < 1e-9) return t;
        t += d;
    }
    return -1;
}

}  // namespace

TEST_CASE("the captured G-buffer of every built-in shape matches a CPU ray cast of the exact shape") {
    const int width = 72, height = 64;
    context::ContextOptions context_options;
    context_options.backend = test::test_backend();
    const auto context = context::create_context(context_options);
    app::EffectOptions options;
    options.path = std::string(FXVIEW_SOURCE_EFFECTS_DIR) + "/spectral/thinfilm.fx";
    options.technique = "FresnelExact";  // any technique that calls fx_capture()
    auto session = app::open_effect_session(options);
    for (const std::string mesh_name : {"sphere", "torus", "cube", "plane", "disc", "knot"}) {
        CAPTURE(mesh_name);
        const ExactShape shape = exact_shape(mesh_name);
        const TessellationBounds bounds = tessellation_bounds(scene::load_mesh(mesh_name), shape);
        scene::Scene scene;
        scene.objects.front().mesh = mesh_name;
        // Turned so that curved parts, edges and faces at several angles face the camera; the flat
        // shapes are tilted but stay in front.
        const bool flat = mesh_name == "plane" || mesh_name == "disc";
        scene.camera.pose.rotation = math::rotation_from_euler_degrees(flat ? glm::vec3(35, -20, 0) : glm::vec3(25, -35, 10));
        gl::RenderTarget target({width, height, 5, 0});
        session->render(scene, target);
        const image::FloatImage positions = target.read_color(1), normals = target.read_color(2);

        const test::PixelRays rays(scene.camera, width, height);
        const glm::dvec3 eye = rays.eye;
        // The camera position the references use is the view matrix's eye.
        const glm::dvec4 origin = glm::inverse(glm::dmat4(math::view_matrix(scene.camera.pose))) * glm::dvec4(0, 0, 0, 1);
        CHECK(glm::length(glm::dvec3(origin) - eye) < 1e-5);
        const auto is_covered = [&positions, width, height](int x, int y) {
            return x >= 0 && y >= 0 && x < width && y < height && positions.pixel(x, y)[3] > 0.0f;
        };

        int checked = 0, edge_pixels = 0;
        double worst_ray = 0, worst_depth = 0, worst_normal = 0;
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x) {
                const glm::dvec3 direction = rays.direction(x, y);
                const double hit_distance = trace(shape, eye, direction);
                const bool covered = is_covered(x, y);
                if ((hit_distance >= 0) != covered) {
                    // Facets and exact shape may disagree only at the edge of what the GPU covered.
                    const bool at_edge = is_covered(x - 1, y) != covered || is_covered(x + 1, y) != covered ||
                                         is_covered(x, y - 1) != covered || is_covered(x, y + 1) != covered;
                    CHECK(at_edge);
                    ++edge_pixels;
                    continue;
                }
                if (!covered) continue;
                const glm::dvec3 hit = eye + hit_distance * direction, exact_normal = shape.normal(hit);
                const double cos_theta = -glm::dot(direction, exact_normal);
                if (cos_theta < 0.25) continue;  // near grazing the sag moves the hit far along the ray
                const glm::dvec3 captured(positions.pixel(x, y)[0], positions.pixel(x, y)[1], positions.pixel(x, y)[2]);
                const glm::dvec3 normal =
                    glm::normalize(glm::dvec3(normals.pixel(x, y)[0], normals.pixel(x, y)[1], normals.pixel(x, y)[2]));
                // On the pixel's ray (float interpolation: 1e-5), at the first surface it meets (within
                // the sag, seen along the ray), with the normal the tessellation allows there.
                worst_ray = std::max(worst_ray, glm::length(glm::cross(captured - eye, direction)));
                worst_depth = std::max(worst_depth, std::abs(glm::dot(captured - eye, direction) - hit_distance) * cos_theta);
                // The normal is compared where the facet lies (the bound is measured there); the exact
                // normal at the ray's hit differs by the sag's lever.
                worst_normal = std::max(worst_normal, std::acos(std::clamp(glm::dot(normal, shape.normal(captured)), -1.0, 1.0)));
                ++checked;
            }
        MESSAGE(mesh_name, ": ", checked, " pixels; off the ray ", worst_ray, ", depth x cos θ ", worst_depth, " (sag ", bounds.sag,
                "), normal ", worst_normal, " rad (bound ", bounds.normal_angle, "); ", edge_pixels, " edge pixels");
        CHECK(checked > 600);
        CHECK(edge_pixels * 20 < checked);
        CHECK(worst_ray < 1e-5);
        CHECK(worst_depth < bounds.sag + 1e-5);
        CHECK(worst_normal < bounds.normal_angle + 1e-4);
    }
}
