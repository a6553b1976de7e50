// Renders through the backend named by FXVIEW_TEST_BACKEND (egl or osmesa; CTest runs both) and
// checks the pictures against geometry: the sphere's centre faces the camera, corners are empty,
// float readback is exact, MSAA and extra colour attachments work.
#include <doctest/doctest.h>

#include "test_support.hpp"

#include <cstdlib>
#include <cstring>

#include "context/context.hpp"
#include "gl/program.hpp"
#include "gl/render_target.hpp"
#include "image/pixel_info.hpp"
#include "render/debug_renderer.hpp"

using namespace fxview;
using fxview::test::shared_context;
using fxview::test::test_backend;

namespace {

image::FloatImage render_sphere(render::DebugView view, int size, int samples = 0) {
    shared_context();
    scene::Scene scene;  // sphere of radius 1 at the origin, camera 3 units away on +Z
    gl::RenderTarget target({size, size, 1, samples});
    render::DebugRenderer renderer;
    renderer.render(scene, view, target);
    REQUIRE(glGetError() == GL_NO_ERROR);
    return target.read_color(0);
}

// At 64x64 pixel (32,32) is half a pixel off the optical axis: the ray leaves the axis by
// tan(22.5 deg)/64 ~ 0.0065 per unit, so it meets the sphere ~0.013 off centre. Interpolating
// vertex normals of a 64x32 tessellation adds < 0.002. 0.02 per component covers both.
constexpr float kNormalTolerance = 0.02f;

}  // namespace

TEST_CASE("the backend gives an OpenGL 4.5 core context") {
    shared_context();
    const auto info = context::query_context_info();
    MESSAGE("backend ", context::backend_name(test_backend()), ": ", info.renderer, " / ", info.version);
    CHECK((info.major > 4 || (info.major == 4 && info.minor >= 5)));
    CHECK(info.core_profile);
    CHECK(!info.renderer.empty());
}

TEST_CASE("normal view of a sphere at 64x64: centre faces the camera, corners are background") {
    const image::FloatImage image = render_sphere(render::DebugView::Normals, 64);
    const auto centre = image::inspect_pixel(image, 32, 32, image::Encoding::Srgb);
    CHECK(centre.rgba[3] == 1.0f);
    CHECK(std::abs(centre.normal.x) < kNormalTolerance);
    CHECK(std::abs(centre.normal.y) < kNormalTolerance);
    CHECK(centre.normal.z > 1.0f - kNormalTolerance);
    // Mapped by eq. 55: the facing normal (0,0,1) is the colour (0.5, 0.5, 1.0).
    CHECK(centre.rgba[0] == doctest::Approx(0.5f).epsilon(kNormalTolerance));
    CHECK(centre.rgba[2] == doctest::Approx(1.0f).epsilon(kNormalTolerance));
    for (const auto& [x, y] : {std::pair{0, 0}, std::pair{63, 0}, std::pair{0, 63}, std::pair{63, 63}}) {
        const float* corner = image.pixel(x, y);
        CHECK(corner[0] == 0.0f);
        CHECK(corner[3] == 0.0f);  // cleared, nothing drawn
    }
    // Image rows run top to bottom: the upper half of the sphere has normals with y > 0.
    const auto upper = image::inspect_pixel(image, 32, 16, image::Encoding::Srgb);
    CHECK(upper.normal.y > 0.3f);
    const auto right = image::inspect_pixel(image, 48, 32, image::Encoding::Srgb);
    CHECK(right.normal.x > 0.3f);
}

TEST_CASE("texture-coordinate and to-camera views at the sphere's centre") {
    const image::FloatImage uv = render_sphere(render::DebugView::TexCoords, 64);
    // u = 0.5 and v = 0.5 face the camera; half a pixel off axis moves them by < 0.005.
    CHECK(uv.pixel(32, 32)[0] == doctest::Approx(0.5f).epsilon(0.01));
    CHECK(uv.pixel(32, 32)[1] == doctest::Approx(0.5f).epsilon(0.01));
    const image::FloatImage to_camera = render_sphere(render::DebugView::ToCamera, 64);
    const auto info = image::inspect_pixel(to_camera, 32, 32, image::Encoding::Srgb);
    CHECK(info.normal.z > 0.999f);  // the camera is straight ahead on +Z
}

TEST_CASE("float readback is exact") {
    shared_context();
    gl::RenderTarget target({8, 4, 2, 0});
    target.bind_for_drawing();
    // Values that 8-bit or half-float storage would change.
    const float first[4] = {0.123456789f, -3.5e-7f, 1234.5678f, 1.0f / 3.0f};
    const float second[4] = {65504.5f, 1e-30f, -2.0f, 0.999999f};
    glClearBufferfv(GL_COLOR, 0, first);
    glClearBufferfv(GL_COLOR, 1, second);
    const image::FloatImage a = target.read_color(0);
    const image::FloatImage b = target.read_color(1);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 8; ++x) {
            CHECK(std::memcmp(a.pixel(x, y), first, sizeof first) == 0);
            CHECK(std::memcmp(b.pixel(x, y), second, sizeof second) == 0);
        }
    CHECK_THROWS_AS(target.read_color(2), Error);
}

TEST_CASE("MSAA resolves to the same interior and softer edges") {
    const image::FloatImage plain = render_sphere(render::DebugView::Normals, 64, 0);
    const image::FloatImage msaa = render_sphere(render::DebugView::Normals, 64, 4);
    // Interior pixels are fully covered: resolving averages equal samples of a smooth field.
    for (int c = 0; c < 4; ++c) CHECK(msaa.pixel(32, 32)[c] == doctest::Approx(plain.pixel(32, 32)[c]).epsilon(1e-3));
    // Some silhouette pixel must be partly covered (alpha strictly between 0 and 1).
    int partial = 0;
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x)
            if (msaa.pixel(x, y)[3] > 0.0f && msaa.pixel(x, y)[3] < 1.0f) ++partial;
    CHECK(partial > 0);
}

TEST_CASE("GLSL errors come back as ShaderError with the driver's log") {
    shared_context();
    CHECK_THROWS_WITH_AS(gl::link_program({{GL_FRAGMENT_SHADER, "#version 450 core\nvoid main() { oops; }\n", "broken.frag"}}),
                         doctest::Contains("broken.frag: fragment shader does not compile"), gl::ShaderError);
}

TEST_CASE("impossible render targets are refused") {
    shared_context();
    CHECK_THROWS_AS(gl::RenderTarget({0, 16, 1, 0}), Error);
    CHECK_THROWS_AS(gl::RenderTarget({16, 16, 99, 0}), Error);
}
