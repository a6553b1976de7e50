// Rough films (thinfilm.fx's Roughness; effects/lib/film_roughness.glsl): the GPU against its CPU
// reference under the sky and the studio, and the approximation against the lobe's integral with the
// film at each direction's half vector (compare --ground-truth), where a uniform light leaves only the
// film's spread of angles; on the backend named by FXVIEW_TEST_BACKEND.
#include <doctest/doctest.h>

#include "app/gpu_cpu_compare.hpp"
#include "test_support.hpp"

using namespace fxview;

namespace {

app::RenderRequest film(const std::string& technique, const std::string& environment, std::vector<std::string> sets) {
    app::RenderRequest request;
    request.backend = test::test_backend();
    request.width = request.height = 32;
    request.effect.path = std::string(FXVIEW_SOURCE_EFFECTS_DIR) + "/spectral/thinfilm.fx";
    request.effect.technique = technique;
    request.effect.sets = std::move(sets);
    request.scene.environment.source = environment;
    return request;
}

}  // namespace

TEST_CASE("rough films match their CPU reference; a wrong roughness on the CPU side fails") {
    // "" is the uniform sky (no environment): the strata then weigh the lobe's directions evenly.
    for (const std::string environment : {"sky:35", "studio", ""})
        for (const std::string technique : {"FresnelExact", "BubbleFourier", "FresnelFourier"}) {
            CAPTURE(environment);
            CAPTURE(technique);
            const app::CompareResult r = app::compare_technique(film(technique, environment, {"Roughness=0.3"}), technique, {});
            CHECK(r.pass);
        }
    // The thesis' models walk the same strata.
    for (const std::string technique : {"Fresnel", "MultiLayer"}) {
        CAPTURE(technique);
        CHECK(app::compare_technique(film(technique, "sky:35", {"Roughness=0.3"}), technique, {}).pass);
    }
    CHECK(!app::compare_technique(film("BubbleFourier", "sky:35", {"Roughness=0.3"}), "BubbleFourier", {"Roughness=0.35"}).pass);
}

TEST_CASE("a rough film against the lobe's integral with the film at each half vector") {
    // In the white furnace a bare substrate (Thickness 0) leaves only the angles' spread: the film in
    // four strata of half-vector angle against the film averaged over the lobe's angles. Measured mean
    // CIEDE2000 0.020 at Roughness 0.2 (one mean angle gave 0.075); a twentieth of a just-noticeable
    // difference is allowed.
    const app::CompareResult bare = app::compare_technique(film("FresnelFourier", "furnace", {"Roughness=0.2", "Thickness=0", "Variation=0"}), "", {}, true);
    REQUIRE(bare.ground_truth);
    MESSAGE("bare substrate, furnace: mean ", bare.ground_truth->mean_delta_e, " max ", bare.ground_truth->max_delta_e);
    CHECK(bare.ground_truth->mean_delta_e < 0.05);
    // A soap bubble under the sky at 0.2: measured mean 0.081, 95th percentile 0.24 (one mean angle
    // gave 0.21 / 0.47: the sun's glint took the colour of the lobe's mean angle, not its own).
    const app::CompareResult bubble = app::compare_technique(film("BubbleFourier", "sky:35", {"Roughness=0.2"}), "", {}, true);
    REQUIRE(bubble.ground_truth);
    MESSAGE("bubble, sky: mean ", bubble.ground_truth->mean_delta_e, " 95th percentile ", bubble.ground_truth->p95_delta_e);
    CHECK(bubble.ground_truth->mean_delta_e < 0.15);
    CHECK(bubble.ground_truth->p95_delta_e < 0.4);
    // A broad lobe: oil on water at 0.7, measured mean 0.23 / 95th percentile 0.57 (one mean angle:
    // 5.5 / 16). Below half a just-noticeable difference on average, and the 95th below one.
    const app::CompareResult broad = app::compare_technique(film("FresnelFourier", "sky:35", {"Roughness=0.7"}), "", {}, true);
    REQUIRE(broad.ground_truth);
    MESSAGE("oil film, sky, Roughness 0.7: mean ", broad.ground_truth->mean_delta_e, " 95th percentile ", broad.ground_truth->p95_delta_e);
    CHECK(broad.ground_truth->mean_delta_e < 0.5);
    CHECK(broad.ground_truth->p95_delta_e < 1.0);
}
