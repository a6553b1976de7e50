// Analytic BRDFs against integrals with closed forms: normalised distributions integrate to one over
// projected microfacet area, the energy-conserving Phong reflects exactly kd + ks at normal
// incidence, Ashikhmin-Shirley's 28/23 constant makes its diffuse albedo Rd (1 − (1 − n·v/2)⁵),
// and the full Fresnel formula equals the exact unpolarised reflectance of viewer/optics.
#include <doctest/doctest.h>

#include <cmath>
#include <functional>
#include <numbers>

#include "brdf/microfacet.hpp"
#include "brdf/models.hpp"
#include "optics/fresnel.hpp"

using namespace fxview;

namespace {

constexpr double kPi = std::numbers::pi;

// 2π ∫₀¹ g(μ) dμ by the midpoint rule: the integral over the hemisphere of a function of cos θ
// alone (dω = dμ dφ). With 200 000 intervals its error is below 1e-8 for the smooth integrands
// here (second derivative times h²/24, h = 5e-6).
double hemisphere(const std::function<double(double)>& g, int intervals = 200000) {
    double sum = 0;
    for (int i = 0; i < intervals; ++i) sum += g((i + 0.5) / intervals);
    return 2.0 * kPi * sum / intervals;
}

glm::dvec3 direction(double cos_theta, double phi) {
    const double s = std::sqrt(std::max(0.0, 1.0 - cos_theta * cos_theta));
    return {s * std::cos(phi), s * std::sin(phi), cos_theta};
}

}  // namespace

TEST_CASE("GGX and Beckmann are normalised: the integral of D(h)(n·h) over the hemisphere is 1") {
    for (const double alpha : {0.1, 0.3, 0.7, 1.0}) {
        CAPTURE(alpha);
        CHECK(hemisphere([&](double mu) { return brdf::ggx_distribution(mu, alpha) * mu; }) == doctest::Approx(1.0).epsilon(1e-6));
    }
    // α = 1 is the uniform distribution of microfacet normals: D = 1/π everywhere.
    CHECK(brdf::ggx_distribution(0.3, 1.0) == doctest::Approx(1.0 / kPi).epsilon(1e-15));
    for (const double m : {0.15, 0.3, 0.6}) {
        CAPTURE(m);
        CHECK(hemisphere([&](double mu) { return brdf::beckmann_distribution(mu, m) * mu; }) == doctest::Approx(1.0).epsilon(1e-6));
        // Seed 001's printed constant 4 instead of π scales the integral to π/4 (DOMAIN.md §7).
        CHECK(hemisphere([&](double mu) { return brdf::beckmann_distribution(mu, m, true) * mu; }) ==
              doctest::Approx(kPi / 4.0).epsilon(1e-6));
    }
}

TEST_CASE("the modified Phong BRDF reflects exactly kd + ks of light arriving along the normal") {
    // With l = n the mirror direction is n, so (r·v)ⁿ = cosⁿθv and ∫ (n+2)/(2π) cosⁿ⁺¹θ dω = 1.
    for (const double exponent : {1.0, 10.0, 200.0}) {
        brdf::ModifiedPhong phong{glm::dvec3(0.3, 0.5, 0.1), 0.45, exponent};
        CAPTURE(exponent);
        for (int c = 0; c < 3; ++c) {
            const double albedo = hemisphere([&](double mu) {
                const brdf::Directions d{{0, 0, 1}, {0, 0, 1}, direction(mu, 0.4), {1, 0, 0}};
                return brdf::evaluate(phong, d)[c] * mu;
            });
            CHECK(albedo == doctest::Approx(phong.kd[c] + phong.ks).epsilon(1e-6));
        }
    }
}

TEST_CASE("Ashikhmin-Shirley's diffuse term: albedo Rd (1 - Rs)(1 - (1 - n·v/2)^5)") {
    // 28/(23π) ∫ (1 − (1 − μ/2)⁵) μ dω = 1 (∫₀¹ (1 − (1 − μ/2)⁵) μ dμ = 23/56), so for a view along the
    // normal the diffuse albedo is Rd (1 − Rs) · 31/32. The specular lobe is switched off by Rs = 0
    // and a huge exponent whose lobe is a few 1e-12 sr wide.
    const brdf::AshikhminShirley model{glm::dvec3(0.6, 0.3, 0.9), glm::dvec3(0.0), 1e9, 1e9};
    for (int c = 0; c < 3; ++c) {
        const double albedo = hemisphere([&](double mu) {
            const brdf::Directions d{{0, 0, 1}, direction(mu, 1.1), {0, 0, 1}, {1, 0, 0}};
            return brdf::evaluate(model, d)[c] * mu;
        });
        CHECK(albedo == doctest::Approx(model.rd[c] * 31.0 / 32.0).epsilon(1e-6));
    }
}

TEST_CASE("the anisotropic exponent follows the tangent: nu along t, nv across") {
    // h tilted by the same angle towards t or towards n × t: the lobe is the isotropic one with
    // exponent nu or nv respectively, so a small nu stretches the highlight along t.
    const brdf::AshikhminShirley aniso{glm::dvec3(0.0), glm::dvec3(1.0), 10.0, 1000.0};
    const glm::dvec3 n(0, 0, 1), t(1, 0, 0), v = glm::normalize(glm::dvec3(0.2, 0.1, 1.0));
    const auto specular = [&](const glm::dvec3& h, double exponent) {
        const glm::dvec3 l = 2.0 * glm::dot(v, h) * h - v;
        const brdf::AshikhminShirley iso{glm::dvec3(0.0), glm::dvec3(1.0), exponent, exponent};
        // Only the normalisation √((nu+1)(nv+1)) differs from the isotropic lobe's (e + 1).
        const double expected = brdf::evaluate(iso, {n, l, v, t}).x * std::sqrt((10.0 + 1) * (1000.0 + 1)) / (exponent + 1);
        return std::pair{brdf::evaluate(aniso, {n, l, v, t}).x, expected};
    };
    const auto [along, along_expected] = specular(glm::normalize(glm::dvec3(0.05, 0, 1)), 10.0);
    const auto [across, across_expected] = specular(glm::normalize(glm::dvec3(0, 0.05, 1)), 1000.0);
    CHECK(along == doctest::Approx(along_expected).epsilon(1e-12));
    CHECK(across == doctest::Approx(across_expected).epsilon(1e-12));
    CHECK(along > 3 * across);  // (n·h)^10 against (n·h)^1000 at n·h = 0.99875: 0.988 against 0.286
}

TEST_CASE("Fresnel: seed 001's full formula is the exact unpolarised reflectance; Schlick's ends are exact") {
    for (const double eta : {1.33, 1.5, 2.4})
        for (const double c : {1.0, 0.9, 0.5, 0.2, 0.01}) {
            CAPTURE(eta);
            CAPTURE(c);
            CHECK(brdf::fresnel_dielectric(eta, c) == doctest::Approx(optics::interface_reflectance(1.0, eta, c)).epsilon(1e-12));
        }
    CHECK(brdf::fresnel_dielectric(1.5, 1.0) == doctest::Approx(0.04).epsilon(1e-12));
    CHECK(brdf::fresnel_dielectric(1.0 / 1.5, 0.5) == 1.0);  // from glass into air at 60°: total reflection
    CHECK(brdf::fresnel_schlick(0.04, 1.0) == doctest::Approx(0.04).epsilon(1e-15));
    CHECK(brdf::fresnel_schlick(0.04, 0.0) == doctest::Approx(1.0).epsilon(1e-15));
}

TEST_CASE("geometry terms: V-cavity and Smith-Schlick-GGX are 1 looking straight down") {
    CHECK(brdf::v_cavity_geometry(1.0, 1.0, 1.0, 1.0) == 1.0);
    CHECK(brdf::smith_schlick_ggx(1.0, 1.0, 0.5) == doctest::Approx(1.0).epsilon(1e-15));
    // Grazing views are shadowed: G1 -> 0 as n·v -> 0.
    CHECK(brdf::smith_schlick_ggx(1e-6, 1.0, 0.5) < 1e-5);
    CHECK(brdf::v_cavity_geometry(0.9, 0.01, 1.0, 0.6) < 0.05);
}

TEST_CASE("every model is zero below the horizon") {
    const brdf::Directions below{{0, 0, 1}, glm::normalize(glm::dvec3(1, 0, -0.1)), {0, 0, 1}, {1, 0, 0}};
    CHECK(brdf::evaluate(brdf::Lambert{}, below) == glm::dvec3(0.0));
    CHECK(brdf::evaluate(brdf::MetallicRoughness{}, below) == glm::dvec3(0.0));
    CHECK(brdf::evaluate(brdf::ModifiedPhong{}, below) == glm::dvec3(0.0));
    CHECK(brdf::evaluate(brdf::CookTorranceBeckmann{}, below) == glm::dvec3(0.0));
    CHECK(brdf::evaluate(brdf::AshikhminShirley{}, below) == glm::dvec3(0.0));
    CHECK(brdf::evaluate(brdf::AshikhminShirleyFit{}, below) == glm::dvec3(0.0));
}
