// The scene light's intensity in photometric units (--light-intensity; scene/light_intensity.hpp):
// conversions against the photometric relations worked by hand here (I = Φ / 4π, E = I / D², a
// Lambertian emitter's Φ = π L A, a sphere's I = L π R²), and the pictures: a white Lambertian surface
// facing the light shows E / π (luminance in cd/m²) whatever the light's spectrum, on the backend
// named by FXVIEW_TEST_BACKEND.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

#include "app/effect_options.hpp"
#include "app/offscreen_render.hpp"
#include "core/error.hpp"
#include "render/effect_session.hpp"
#include "scene/scene.hpp"
#include "test_support.hpp"

using namespace fxview;

namespace {

constexpr double kPi = std::numbers::pi;

scene::Light light_at(glm::vec3 position, scene::LightShape shape = scene::LightShape::Sphere, float radius = 0, glm::vec2 size = {}) {
    scene::Light light;
    light.pose.position = position;
    light.shape = shape;
    light.radius = radius;
    light.size = size;
    return light;
}

double lux(const scene::Light& light, const std::string& text) {
    const auto intensity = scene::parse_light_intensity(text);
    REQUIRE(intensity);
    return scene::illuminance_at_origin(light, *intensity);
}

// Linear sRGB to luminance (IEC 61966-2-1's Y row).
double luminance(const float* rgb) { return 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2]; }

}  // namespace

TEST_CASE("photometric units come down to the illuminance at the origin") {
    const scene::Light point = light_at({0, 0, 2});
    CHECK(lux(point, "500lx") == 500.0);
    CHECK(lux(point, "100 cd") == doctest::Approx(25.0));                  // E = I / D²
    CHECK(lux(point, "800lm") == doctest::Approx(800.0 / (4 * kPi) / 4));  // I = Φ / 4π: 15.92 lx
    // A sphere of luminance L: I = L π R² (its disc), E = I / D² = 1000 π 0.25 / 4.
    CHECK(lux(light_at({0, 0, 2}, scene::LightShape::Sphere, 0.5f), "1000nit") == doctest::Approx(1000 * kPi * 0.25 / 4));
    // A disc facing the origin: E = π L R² / (R² + D²); its flux π L A gives the same E back.
    const scene::Light disc = light_at({0, 2, 0}, scene::LightShape::Disc, 0.5f);
    CHECK(lux(disc, "1000nit") == doctest::Approx(kPi * 1000 * 0.25 / 4.25));
    CHECK(lux(disc, std::to_string(kPi * 1000 * kPi * 0.25) + "lm") == doctest::Approx(kPi * 1000 * 0.25 / 4.25));
    CHECK(lux(disc, std::to_string(1000 * kPi * 0.25) + "cd") == doctest::Approx(kPi * 1000 * 0.25 / 4.25));  // axial I = L A
    // A rectangle 2 x 1 at 3: E = L x the closed form (checked against Lambert's formula in test_light_shapes).
    const scene::Light window = light_at({0, 0, 3}, scene::LightShape::Rectangle, 0, {2, 1});
    CHECK(lux(window, "500nit") == doctest::Approx(500 * scene::flat_light_irradiance_at_origin(scene::LightShape::Rectangle, {1, 0.5}, 3)));
    // A point has no luminance; lumens of a light at the origin have no distance.
    CHECK_THROWS_AS(lux(point, "1000nit"), UsageError);
    CHECK_THROWS_AS(lux(light_at({0, 0, 0}), "800lm"), UsageError);
    for (const char* bad : {"500", "-3lx", "nanlx", "5 W", "lx", ""}) {
        CAPTURE(bad);
        CHECK_FALSE(scene::parse_light_intensity(bad));
    }
    CHECK(scene::parse_light_intensity("3000 cd/m2")->unit == scene::LightIntensity::Unit::Nit);
}

TEST_CASE("a white Lambertian surface facing a light of E lux shows E / pi, whatever the light's spectrum") {
    // The light at the camera (0, 0, 3): the sphere's centre pixel faces it (n·l = 1).
    const auto centre_luminance = [](const std::string& effect, const std::string& technique, std::vector<std::string> sets, const std::string& spectrum) {
        app::RenderRequest request;
        request.backend = test::test_backend();
        request.width = request.height = 33;
        request.effect.path = std::string(FXVIEW_SOURCE_EFFECTS_DIR) + effect;
        request.effect.technique = technique;
        request.effect.sets = std::move(sets);
        request.scene.light.pose.position = glm::vec3(0.0f, 0.0f, 3.0f);
        request.scene.light.intensity = scene::parse_light_intensity("120lx");
        request.scene.light.spectrum = spectrum;
        const image::FloatImage image = app::render_offscreen(request);
        return luminance(image.pixel(16, 16));
    };
    // 120 / π = 38.2; 0.2 %: the pixel centre's normal is within 0.05° of the light, and the spectral
    // sums' float rounding is 1e-6; Y here is from the sRGB primaries, which reproduce D65's XYZ to 1e-4.
    for (const std::string spectrum : {"D65", "F11", "A"}) {
        CAPTURE(spectrum);
        CHECK(centre_luminance("/spectral/wavelength.fx", "Lambert", {"Kd=1", "ObjectSpectrum=E"}, spectrum) == doctest::Approx(120 / kPi).epsilon(2e-3));
    }
    CHECK(centre_luminance("/brdf/analytic.fx", "Lambert", {"BaseColor=1,1,1"}, "") == doctest::Approx(120 / kPi).epsilon(2e-3));
}

TEST_CASE("an intensity no parameter takes is said") {
    test::shared_context();
    scene::Light light;
    light.intensity = scene::parse_light_intensity("500lx");
    app::EffectOptions film;
    film.path = std::string(FXVIEW_SOURCE_EFFECTS_DIR) + "/spectral/thinfilm.fx";
    CHECK(app::open_effect_session(film)->unused_light_intensity_warning(light).find("500 lx changes nothing") != std::string::npos);
    app::EffectOptions cd;
    cd.path = std::string(FXVIEW_SOURCE_EFFECTS_DIR) + "/spectral/cd.fx";
    CHECK(app::open_effect_session(cd)->unused_light_intensity_warning(light).empty());  // its Lamp follows
}
