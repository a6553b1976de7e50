// The GPU-vs-CPU contract on the backend named by FXVIEW_TEST_BACKEND: every technique of
// effects/spectral passes `compare` on a sphere at 128x128 (with float and 8-bit CMFs, both
// observers, coarse steps), and fails when the CPU side alone gets a wrong parameter.
#include <doctest/doctest.h>

#include "app/gpu_cpu_compare.hpp"
#include "test_support.hpp"

using namespace fxview;

namespace {

app::RenderRequest sphere_request(std::vector<std::string> sets = {}) {
    app::RenderRequest request;
    request.backend = test::test_backend();
    request.width = request.height = 128;
    request.effect.path = std::string(FXVIEW_SOURCE_EFFECTS_DIR) + "/spectral/wavelength.fx";
    request.effect.sets = std::move(sets);
    return request;
}

}  // namespace

TEST_CASE("every spectral technique matches its CPU reference") {
    const auto techniques = app::technique_names(std::string(FXVIEW_SOURCE_EFFECTS_DIR) + "/spectral/wavelength.fx");
    CHECK(techniques.size() == 8);
    for (const auto& variant : std::vector<std::vector<std::string>>{
             {}, {"ByteCmf=true", "Observer=1", "Steps=5", "ObjectSpectrum=TCS09", "OutputMode=1"},
             {"LightSpectrum=F11", "Lower=400", "Upper=700", "K=0.01", "OutputMode=2", "Metal=true"}}) {
        for (const auto& technique : techniques) {
            CAPTURE(technique);
            CAPTURE(variant.size());
            const app::CompareResult r = app::compare_technique(sphere_request(variant), technique, {});
            CHECK(r.has_reference);
            CHECK(r.pixels > 5000);  // the sphere covers about 9360 of 16384 pixels
            CHECK(r.mismatched_8bit == 0);
            CHECK(r.max_abs_error <= r.tolerance);
            CHECK(r.pass);
            MESSAGE(technique, ": max ", r.max_abs_error, " mean ", r.mean_abs_error);
        }
    }
}

TEST_CASE("a wrong parameter on the CPU side only makes the comparison fail") {
    for (const char* wrong : {"Kd=0.7", "ObjectSpectrum=TCS01", "Observer=1", "Steps=10"}) {
        CAPTURE(wrong);
        const app::CompareResult r = app::compare_technique(sphere_request(), "Phong", {wrong});
        CHECK(r.has_reference);
        CHECK(!r.pass);
        CHECK(r.max_abs_error > r.tolerance);
    }
}

TEST_CASE("a technique without a reference is reported, never skipped") {
    app::RenderRequest request = sphere_request();
    request.effect.path = std::string(FXVIEW_SOURCE_EFFECTS_DIR) + "/examples/textured.fx";
    const app::CompareResult r = app::compare_technique(request, "Mirror", {});
    CHECK(!r.has_reference);
    CHECK(!r.pass);
}

TEST_CASE("the debug views and Plain match their CPU references") {
    app::RenderRequest request = sphere_request();
    request.effect.path = std::string(FXVIEW_SOURCE_EFFECTS_DIR) + "/debug.fx";
    request.scene.objects.front().mesh = "torus";
    request.scene.objects.front().pose.rotation = glm::angleAxis(0.6f, glm::normalize(glm::vec3(1, 1, 0)));
    for (const auto& technique : app::technique_names(request.effect.path)) {
        CAPTURE(technique);
        const app::CompareResult r = app::compare_technique(request, technique, {});
        CHECK(r.has_reference);
        CHECK(r.pass);
    }
    const app::CompareResult wrong = app::compare_technique(request, "Plain", {"Ambient=0.5"});
    CHECK(!wrong.pass);
}

TEST_CASE("a texture read through the CPU sampler: CheckerLambert matches, a wrong tiling does not") {
    app::RenderRequest request = sphere_request();
    request.effect.path = std::string(FXVIEW_SOURCE_EFFECTS_DIR) + "/examples/textured.fx";
    request.scene.objects.front().mesh = "torus";
    const app::CompareResult r = app::compare_technique(request, "CheckerLambert", {});
    CHECK(r.has_reference);
    CHECK(r.mismatched_8bit == 0);
    CHECK(r.pass);
    MESSAGE("CheckerLambert: max ", r.max_abs_error, " mean ", r.mean_abs_error);
    CHECK(!app::compare_technique(request, "CheckerLambert", {"Tiling=3"}).pass);
}
