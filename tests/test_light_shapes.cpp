// Flat scene lights (--light-shape disc|rectangle; scene/light_geometry.hpp, effects/lib/area_light.glsl):
// their irradiance against closed forms nobody here wrote (a disc's on its axis; Lambert's formula for
// polygons), the GPU's quadrature against the integral, the blurred image's energy, and the CD's
// rainbow sector under a disc light against the grating equation, on the backend named by FXVIEW_TEST_BACKEND.
#include <doctest/doctest.h>

#include <cmath>
#include <fstream>
#include <numbers>

#include "app/gpu_cpu_compare.hpp"
#include "app/offscreen_render.hpp"
#include "app/scene_options.hpp"
#include "core/error.hpp"
#include "reference/flat_lamp.hpp"
#include "render/effect_session.hpp"
#include "app/effect_options.hpp"
#include "spectral/color_difference.hpp"
#include "spectral/level_of_detail.hpp"
#include "pixel_rays.hpp"
#include "test_support.hpp"

using namespace fxview;

namespace {

constexpr double kPi = std::numbers::pi;

// Lambert's formula: the irradiance at the origin on a surface of normal n from a polygon of unit
// radiance, (1/2) Σ γ_i n·(v_i × v_i+1)/|v_i × v_i+1|, γ_i the angle its edge subtends (the whole
// polygon above the surface).
double lambert_polygon(const std::vector<glm::dvec3>& corners, const glm::dvec3& n) {
    double sum = 0;
    for (size_t i = 0; i < corners.size(); ++i) {
        const glm::dvec3 a = glm::normalize(corners[i]), b = glm::normalize(corners[(i + 1) % corners.size()]);
        const glm::dvec3 c = glm::cross(a, b);
        sum += std::acos(std::clamp(glm::dot(a, b), -1.0, 1.0)) * glm::dot(n, glm::normalize(c));
    }
    return 0.5 * std::abs(sum);
}

scene::Light flat_light(scene::LightShape shape, glm::vec3 position, float radius, glm::vec2 size) {
    scene::Light light;
    light.shape = shape;
    light.pose.position = position;
    light.radius = radius;
    light.size = size;
    return light;
}

}  // namespace

TEST_CASE("a flat light's irradiance at the origin: closed forms against Lambert's polygon formula") {
    for (const double distance : {0.5, 2.0, 4.1, 30.0}) {
        CAPTURE(distance);
        const glm::dvec3 centre(0, 0, distance), n(0, 0, 1);
        // A disc as a 4096-gon: its area falls short by (2π²/3)/N² ≈ 4e-7 of the disc's.
        std::vector<glm::dvec3> gon;
        for (int i = 0; i < 4096; ++i) gon.push_back(centre + 0.8 * glm::dvec3(std::cos(2 * kPi * i / 4096), std::sin(2 * kPi * i / 4096), 0));
        CHECK(scene::flat_light_irradiance_at_origin(scene::LightShape::Disc, glm::dvec2(0.8), distance) ==
              doctest::Approx(lambert_polygon(gon, n)).epsilon(2e-6));
        const std::vector<glm::dvec3> rectangle = {centre + glm::dvec3(-1.5, -0.5, 0), centre + glm::dvec3(1.5, -0.5, 0),
                                                   centre + glm::dvec3(1.5, 0.5, 0), centre + glm::dvec3(-1.5, 0.5, 0)};
        // Both exact: only rounding (1e-12) between them.
        CHECK(scene::flat_light_irradiance_at_origin(scene::LightShape::Rectangle, glm::dvec2(1.5, 0.5), distance) ==
              doctest::Approx(lambert_polygon(rectangle, n)).epsilon(1e-9));
    }
}

TEST_CASE("a flat light gives the point light's irradiance at the origin; the GPU's quadrature follows the integral") {
    for (const auto& light : {flat_light(scene::LightShape::Disc, {2, 2, 3}, 1.1f, {}), flat_light(scene::LightShape::Rectangle, {0, 3, 0.5f}, 0, {3, 1}),
                              flat_light(scene::LightShape::Disc, {0, 0.4f, 4}, 0.2f, {})}) {
        const scene::LightGeometry g = scene::light_geometry(light);
        CAPTURE(std::string(scene::light_shape_name(g.shape)));
        CAPTURE(g.centre.y);
        REQUIRE(g.is_flat());
        const glm::dvec3 facing = glm::normalize(g.centre), v(0, 0, 1);
        // The integral's midpoint rule over 18432 or 25600 elements: well within 1e-4 of the exact 1.
        CHECK(reference::flat_lamp_integral(g, glm::dvec3(0), facing, v, 1).lambert == doctest::Approx(1.0).epsilon(1e-4));
        // Elsewhere: the GPU's 34-233 points against the integral, the horizon crossing the light included.
        for (const glm::dvec3 position : {glm::dvec3(0.5, 0.2, 0.7), glm::dvec3(-0.6, 0.5, 0.3), glm::dvec3(0.3, -0.9, 0.1)})
            for (const glm::dvec3 n : {glm::normalize(position), glm::dvec3(0, 1, 0), glm::normalize(glm::dvec3(1, 0.05, 0))})
                for (const double power : {1.0, 32.0, 256.0}) {
                    CAPTURE(position.x);
                    CAPTURE(n.x);
                    CAPTURE(power);
                    const glm::dvec3 view = glm::normalize(glm::dvec3(0, 0, 3) - position);
                    const reference::LampFactors sum = reference::flat_lamp_factors(g, position, n, view, power, true);
                    const reference::LampFactors exact = reference::flat_lamp_integral(g, position, n, view, power);
                    // The sunflower and lattice rules of 34+ points: a smooth cosine within 1 % of the
                    // light's full irradiance (measured at most 0.4 %); a lobe within 3 % of its largest value
                    // over the light (measured 1 %: 4 Ω p points keep neighbours inside the lobe's width).
                    CHECK(std::abs(sum.lambert - exact.lambert) < 0.01 * std::max(exact.lambert, 0.05));
                    const double peak = std::max({exact.phong, exact.blinn, 1e-3});
                    CHECK(std::abs(sum.phong - exact.phong) < 0.03 * peak + 1e-4);
                    CHECK(std::abs(sum.blinn - exact.blinn) < 0.03 * peak + 1e-4);
                }
    }
}

TEST_CASE("a flat light blurred by an order's width keeps its energy") {
    // The radiance over all directions from a point below the light, by a fine grid of directions
    // about its centre: the blurred image holds the sharp light's energy (the ramp's normalisation).
    for (const auto& light : {flat_light(scene::LightShape::Disc, {0, 0, 4}, 0.6f, {}), flat_light(scene::LightShape::Rectangle, {0, 0, 4}, 0, {1.6f, 0.5f})}) {
        const scene::LightGeometry g = scene::light_geometry(light);
        CAPTURE(std::string(scene::light_shape_name(g.shape)));
        const glm::dvec3 position(0.2, -0.1, 0.0);
        const auto energy = [&](double width) {
            constexpr int kSteps = 600;
            constexpr double kReach = 0.5;  // radians about the centre: the light (≤ 0.21) plus half the widest blur
            const glm::dvec3 axis = glm::normalize(g.centre - position), x = glm::normalize(glm::cross(axis, glm::dvec3(0, 1, 0))),
                             y = glm::cross(axis, x);
            double sum = 0;
            for (int i = 0; i < kSteps; ++i)
                for (int k = 0; k < kSteps; ++k) {
                    const double a = kReach * (2.0 * (i + 0.5) / kSteps - 1), b = kReach * (2.0 * (k + 0.5) / kSteps - 1);
                    const glm::dvec3 d = axis + a * x + b * y;  // a gnomonic grid: dω = dA / |d|³
                    sum += scene::flat_light_radiance(g, position, glm::normalize(d), width) / std::pow(glm::length(d), 3.0);
                }
            return sum * std::pow(2.0 * kReach / kSteps, 2.0);
        };
        const double sharp = energy(0.0);
        for (const double width : {0.02, 0.1, 0.3, 0.5}) {
            CAPTURE(width);
            // 3 %: the normalisation takes the light's outline as seen from its centre's direction
            // (a foreshortened disc as an ellipse); what remains is the outline's curvature across the ramp.
            CHECK(energy(width) == doctest::Approx(sharp).epsilon(0.03));
        }
    }
}

TEST_CASE("wavelength.fx under flat lights matches its CPU reference and the integral over the light") {
    for (const scene::LightShape shape : {scene::LightShape::Disc, scene::LightShape::Rectangle}) {
        CAPTURE(std::string(scene::light_shape_name(shape)));
        app::RenderRequest request;
        request.backend = test::test_backend();
        request.width = request.height = 40;
        request.effect.path = std::string(FXVIEW_SOURCE_EFFECTS_DIR) + "/spectral/wavelength.fx";
        request.scene.light.shape = shape;
        request.scene.light.radius = 1.1f;                  // 15° seen from the origin
        request.scene.light.size = glm::vec2(3.0f, 1.0f);  // a window
        for (const std::string technique : {"Lambert", "Phong", "Blinn"}) {
            CAPTURE(technique);
            const app::CompareResult r = app::compare_technique(request, technique, {}, true);
            CHECK(r.pass);
            REQUIRE(r.ground_truth);
            MESSAGE(std::string(scene::light_shape_name(shape)), " ", technique, ": GPU-CPU max ", r.max_abs_error, "; against the integral CIEDE2000 mean ",
                    r.ground_truth->mean_delta_e, " max ", r.ground_truth->max_delta_e);
            // The GPU's 34-233 points against 18432-25600 elements: measured mean 0.01-0.07, max 0.3
            // (a highlight of power 32 at the light's edge); 0.2 and 1 leave room for other drivers.
            CHECK(r.ground_truth->mean_delta_e < 0.2);
            CHECK(r.ground_truth->max_delta_e < 1.0);
        }
        CHECK(!app::compare_technique(request, "Phong", {"Power=40"}).pass);  // a wrong lobe on the CPU side fails
    }
}

TEST_CASE("the CD under a disc light shows the rainbow sector that the grating equation predicts") {
    // The disc faces the camera at (0, 0, 3); a disc light 15° across (seen from the origin) above
    // the camera. A first or second order of 400-700 nm reaches the eye from a disc point where the
    // direction the grating equation gives (tangential components m λ/d − v across the tracks, −v
    // along them) meets the light: the sector of azimuths around the disc's centre where that happens.
    for (const scene::LightShape shape : {scene::LightShape::Disc, scene::LightShape::Rectangle}) {
        CAPTURE(std::string(scene::light_shape_name(shape)));
        const int size = 128;
        app::RenderRequest request;
        request.backend = test::test_backend();
        request.width = request.height = size;
        request.effect.path = std::string(FXVIEW_SOURCE_EFFECTS_DIR) + "/spectral/cd.fx";
        request.effect.technique = "Orders";
        request.effect.sets = {"SubstrateWeight=0", "EnvironmentWeight=0", "Tracks=200", "LightSpectrum=D65"};
        request.scene.objects.front().mesh = "disc";
        request.scene.light.pose.position = glm::vec3(0.0f, 1.5f, 3.0f);
        request.scene.light.shape = shape;
        const double distance = std::hypot(1.5, 3.0), reach = distance * std::tan(15 * kPi / 180);
        request.scene.light.radius = static_cast<float>(reach);
        request.scene.light.size = glm::vec2(static_cast<float>(2 * reach));
        const scene::LightGeometry g = scene::light_geometry(request.scene.light);
        const image::FloatImage image = app::render_offscreen(request);
        const test::PixelRays rays(request.scene.camera, size, size);
        // The lower sector (below the disc's centre, away from the mirror image): its azimuth range,
        // lit where any order of any visible wavelength arrives, rendered where the picture is lit.
        constexpr int kBins = 90;  // 2° of azimuth each over the lower half
        std::vector<int> predicted(kBins, 0), rendered(kBins, 0);
        double brightest = 0;
        for (int y = 0; y < size; ++y)
            for (int x = 0; x < size; ++x) brightest = std::max(brightest, static_cast<double>(image.pixel(x, y)[1]));
        double most_saturated = 0;
        for (int y = 0; y < size; ++y)
            for (int x = 0; x < size; ++x) {
                const glm::dvec3 d = rays.direction(x, y);
                const glm::dvec3 hit = rays.eye - rays.eye.z / d.z * d;
                const double r = glm::length(hit);
                if (r > 0.95 || r < 0.25 || hit.y >= 0) continue;
                const int bin = std::min(static_cast<int>((std::atan2(hit.y, hit.x) + kPi) / kPi * kBins), kBins - 1);
                const glm::dvec3 v = -d, across = glm::normalize(glm::dvec3(hit.x, hit.y, 0)), along = glm::cross(glm::dvec3(0, 0, 1), across);
                bool lit = false;
                for (int m = -3; m <= 3 && !lit; ++m)
                    for (int nm = 400; nm <= 700 && !lit; nm += 5) {
                        const double tx = m * nm / 1600.0 - glm::dot(v, across), ty = -glm::dot(v, along), z2 = 1 - tx * tx - ty * ty;
                        if (z2 <= 0) continue;
                        const glm::dvec3 l = tx * across + ty * along + std::sqrt(z2) * glm::dvec3(0, 0, 1);
                        // Where the ray towards l meets the light's plane, inside its outline?
                        const double t = glm::dot(g.centre - hit, g.normal) / glm::dot(l, g.normal);
                        if (t <= 0) continue;
                        const glm::dvec3 q = hit + t * l - g.centre;
                        const double u = glm::dot(q, g.u), w = glm::dot(q, g.v);
                        lit = shape == scene::LightShape::Disc ? std::hypot(u, w) < reach : std::abs(u) < reach && std::abs(w) < reach;
                    }
                predicted[static_cast<size_t>(bin)] += lit;
                const float* rgb = image.pixel(x, y);
                rendered[static_cast<size_t>(bin)] += rgb[1] > 0.01 * brightest;
                const spectral::Vec3 xyz{0.4124 * rgb[0] + 0.3576 * rgb[1] + 0.1805 * rgb[2], 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2],
                                         0.0193 * rgb[0] + 0.1192 * rgb[1] + 0.9505 * rgb[2]};
                if (xyz[1] > 0.05 * brightest) {
                    const spectral::Vec3 white{0.95047 * xyz[1], xyz[1], 1.08883 * xyz[1]};
                    most_saturated = std::max(most_saturated, spectral::delta_e_2000(spectral::xyz_to_lab(xyz, white), {100, 0, 0}));
                }
            }
        int predicted_bins = 0, rendered_bins = 0;
        for (int b = 0; b < kBins; ++b) {
            predicted_bins += predicted[static_cast<size_t>(b)] > 0;
            rendered_bins += rendered[static_cast<size_t>(b)] > 0;
        }
        MESSAGE(std::string(scene::light_shape_name(shape)), ": sector opening predicted ", 2 * predicted_bins, "°, rendered ", 2 * rendered_bins,
                "°; most saturated pixel ΔE00 ", most_saturated, " from neutral");
        CHECK(predicted_bins > 10);  // a sector tens of degrees wide, not a streak
        CHECK(rendered_bins == doctest::Approx(predicted_bins).epsilon(0.2));  // the 20 %
        CHECK(most_saturated > 20.0);  // a rainbow, not grey: spectral colours lie 40-100 ΔE00 from white
    }
}

TEST_CASE("films mirror a sized light: its radiance times the film's reflectance, matching the CPU reference") {
    // A bare substrate (Thickness 0, n 1.5: R = 0.04 at normal incidence, independent of λ) seen head-on
    // from (0, 0, 3); a disc light of radius 0.8 at (0, 0, 4) facing the origin, mirrored at the
    // sphere's centre pixel. There the film reflects the uniform sky of the light spectrum plus the
    // lamp, whose radiance over the sky's is π L = (R² + D²) / R² (it gives the sky's irradiance at the
    // origin): the centre is 1 + 16.64 / 0.64 = 27 times a pixel beside the image.
    app::RenderRequest request;
    request.backend = test::test_backend();
    request.width = request.height = 161;  // the image's edge is blurred over ~2 pixels: 0.3 % of its light moves out
    request.effect.path = std::string(FXVIEW_SOURCE_EFFECTS_DIR) + "/spectral/thinfilm.fx";
    request.effect.technique = "FresnelExact";
    request.effect.sets = {"Thickness=0", "Variation=0", "SubstrateIndex=1.5", "OutputMode=3"};
    request.scene.light.pose.position = glm::vec3(0.0f, 0.0f, 4.0f);
    request.scene.light.shape = scene::LightShape::Disc;
    request.scene.light.radius = 0.8f;
    const image::FloatImage image = app::render_offscreen(request);
    // Beside the image: a pixel whose mirror direction has turned far past the image (its radius is
    // 9.5°), where the film reflects the sky alone with R(θ) by Fresnel's equations (s and p averaged).
    const test::PixelRays rays(request.scene.camera, 161, 161);
    const glm::dvec3 d = rays.direction(80, 40), eye = rays.eye;
    const double b = glm::dot(eye, d), t = -b - std::sqrt(b * b - (glm::dot(eye, eye) - 1.0));  // the unit sphere
    const double cos_i = glm::dot(glm::normalize(eye + t * d), -d), sin_t = std::sqrt(1 - cos_i * cos_i) / 1.5, cos_t = std::sqrt(1 - sin_t * sin_t);
    const double rs = (cos_i - 1.5 * cos_t) / (cos_i + 1.5 * cos_t), rp = (1.5 * cos_i - cos_t) / (1.5 * cos_i + cos_t);
    const double r_beside = 0.5 * (rs * rs + rp * rp), r_normal = 0.04;
    const double centre = image.pixel(80, 80)[1], beside = image.pixel(80, 40)[1];
    MESSAGE("centre ", centre, " beside ", beside, " at ", std::acos(cos_i) * 180 / kPi, "° (R ", r_beside, "), ratio ", centre / beside);
    // 1 %: the blur keeps the lamp's energy by dimming its inside by w²/12ρ² (0.3 % here); the centre
    // pixel is on the axis; float rounding is far below.
    CHECK(centre / beside == doctest::Approx(27.0 * r_normal / r_beside).epsilon(0.01));

    for (const scene::LightShape shape : {scene::LightShape::Sphere, scene::LightShape::Disc, scene::LightShape::Rectangle}) {
        CAPTURE(std::string(scene::light_shape_name(shape)));
        app::RenderRequest lit;
        lit.backend = test::test_backend();
        lit.width = lit.height = 48;
        lit.effect.path = request.effect.path;
        lit.scene.light.pose.position = glm::vec3(1.0f, 1.0f, 4.0f);
        lit.scene.light.shape = shape;
        lit.scene.light.radius = 0.8f;
        lit.scene.light.size = glm::vec2(2.0f, 1.0f);
        for (const std::string technique : {"FresnelExact", "BubbleFourier", "FresnelFourier"}) {
            CAPTURE(technique);
            CHECK(app::compare_technique(lit, technique, {}).pass);
        }
        lit.scene.environment.source = "sky";  // under the sky the Fourier films sum a lamp's image exactly
        CHECK(app::compare_technique(lit, "BubbleFourier", {}).pass);
    }
}

TEST_CASE("light shapes from the command line and presets; what cannot be drawn is refused or said") {
    const auto request = [](const std::vector<std::string>& arguments) {
        CLI::App app;
        app::SceneOptions options;
        app::add_scene_options(app, options);
        std::vector<std::string> reversed(arguments.rbegin(), arguments.rend());
        app.parse(reversed);
        return app::to_render_request(options);
    };
    const app::RenderRequest disc = request({"--light-shape", "disc", "--light-angle", "15"});
    CHECK(disc.scene.light.shape == scene::LightShape::Disc);
    // A disc facing the origin subtends atan(R / D): R = D tan 15°.
    CHECK(disc.scene.light.radius == doctest::Approx(std::sqrt(17.0) * std::tan(15 * kPi / 180)).epsilon(1e-6));
    const app::RenderRequest window = request({"--light-shape", "rectangle", "--light-size", "2,1"});
    CHECK(window.scene.light.size == glm::vec2(2, 1));
    CHECK_THROWS_AS(request({"--light-shape", "triangle"}), UsageError);
    CHECK_THROWS_AS(request({"--light-shape", "disc"}), UsageError);  // no size: not silently a point
    CHECK_THROWS_AS(request({"--light-size", "2,1"}), UsageError);     // a sphere has no width and height
    CHECK_THROWS_AS(request({"--light-shape", "rectangle", "--light-size", "2,-1"}), UsageError);

    const std::string preset = test::temp_path("window-light.json");
    std::ofstream(preset) << "{\"scene\": {\"light_shape\": \"rectangle\",\n \"light_size\": [3, 1]}}";
    const app::RenderRequest from_preset = request({"--preset", preset});
    CHECK(from_preset.scene.light.shape == scene::LightShape::Rectangle);
    CHECK(from_preset.scene.light.size == glm::vec2(3, 1));
    std::ofstream(preset) << "{\"scene\": {\"light_shape\": \"rectangle\",\n \"light_size\": [3]}}";
    try {
        request({"--preset", preset});
        FAIL("a one-number light_size was taken");
    } catch (const Error& error) {
        CHECK(std::string(error.what()).find(preset + ":2:") != std::string::npos);  // names file and line
    }

    // Techniques that see the light as a point or a sphere say so.
    test::shared_context();
    scene::Light light = flat_light(scene::LightShape::Rectangle, {2, 2, 3}, 0, {2, 1});
    const std::string effects = std::string(FXVIEW_SOURCE_EFFECTS_DIR) + "/spectral/";
    app::EffectOptions thesis_options;
    thesis_options.path = effects + "cd.fx";
    thesis_options.technique = "Thesis";
    CHECK(app::open_effect_session(thesis_options)->unused_light_radius_warning(light).find("as a point") != std::string::npos);
    app::EffectOptions cd_options;
    cd_options.path = effects + "cd.fx";
    CHECK(app::open_effect_session(cd_options)->unused_light_radius_warning(light).empty());  // Orders draws it
}
