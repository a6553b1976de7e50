// Analytic BRDFs from viewer/brdf (double precision): L = f(l, v) · E · (n·l) at each pixel, with the
// directions built from the captured position, normal and tangent.
#include "reference/brdf_reference.hpp"

#include <algorithm>
#include <cmath>

#include "brdf/models.hpp"

namespace fxview::reference {
namespace {

glm::dvec3 colour(const ReferenceContext& c, const std::string& name) {
    const auto& v = c.values.numbers.at(name);
    return {v.at(0), v.at(1), v.at(2)};
}

brdf::Directions directions(const ShadingInput& in) {
    brdf::Directions d;
    d.n = glm::normalize(in.normal);
    d.l = glm::normalize(in.light - in.position);
    d.v = glm::normalize(in.camera - in.position);
    // The tangent made orthogonal to n; any perpendicular where the mesh's tangent is parallel to n.
    glm::dvec3 t = in.tangent - d.n * glm::dot(d.n, in.tangent);
    if (glm::dot(t, t) < 1e-12) t = glm::cross(d.n, std::abs(d.n.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0));
    d.t = glm::normalize(t);
    return d;
}

template <typename Model>
glm::dvec3 radiance(const Model& model, const brdf::Directions& d, double irradiance) {
    return brdf::evaluate(model, d) * irradiance * std::max(glm::dot(d.n, d.l), 0.0);
}

// The GPU's cosines are float: n·h near 1 is only known to a few ulps (~2.4e-7 absolute), which near
// a highlight's peak is an angle of sqrt(2 · 2.4e-7) = 7e-4 rad, far from the peak about 2.4e-7 /
// sin θh. The slack is how much the radiance changes when the normal tilts by that angle (either way,
// about two axes): large only where the lobe is steep, in sharp highlights.
constexpr double kCosineUlps = 2.4e-7;

template <typename Model>
double tilt_sensitivity(const Model& model, const brdf::Directions& d, double irradiance) {
    const glm::dvec3 h = glm::normalize(d.l + d.v);
    const double cos_h = std::clamp(glm::dot(d.n, h), 0.0, 1.0), sin_h = std::sqrt(1.0 - cos_h * cos_h);
    // The tilt δ that moves n·h by kCosineUlps: cos·δ²/2 + sin·δ = ε.
    const double tilt = cos_h > 0 ? std::max((-sin_h + std::sqrt(sin_h * sin_h + 2.0 * cos_h * kCosineUlps)) / cos_h, 4e-7) : 4e-7;
    glm::dvec3 axis = glm::cross(d.n, h);
    axis = glm::dot(axis, axis) > 1e-20 ? glm::normalize(axis) : d.t;
    const glm::dvec3 centre = radiance(model, d, irradiance);
    double spread = 0;
    for (const glm::dvec3& towards : {axis, glm::cross(d.n, axis)})
        for (const double sign : {-1.0, 1.0}) {
            brdf::Directions tilted = d;
            tilted.n = glm::normalize(d.n + sign * tilt * towards);
            const glm::dvec3 change = glm::abs(radiance(model, tilted, irradiance) - centre);
            spread = std::max({spread, change.r, change.g, change.b});
        }
    return spread;
}

template <typename ModelFromParameters>
Reference make(ModelFromParameters model_from, double tolerance, std::string why) {
    Reference r;
    r.shade = [model_from](const ShadingInput& in, const ReferenceContext& c) {
        const glm::dvec3 l = radiance(model_from(c), directions(in), c.number("LightIrradiance"));
        return std::array<double, 4>{l.r, l.g, l.b, 1.0};
    };
    r.slack = [model_from](const ShadingInput& in, const ReferenceContext& c) {
        return tilt_sensitivity(model_from(c), directions(in), c.number("LightIrradiance"));
    };
    r.tolerance = tolerance;
    r.why = std::move(why);
    return r;
}

const char* kWhy = "float32 against double on radiances of order 1: a few ulps of the cosines and of pow/exp (measured "
                   "on llvmpipe below 3e-5 outside highlights); in highlights, where moving n.h by its float "
                   "rounding (2.4e-7) moves the radiance by more, that change is the pixel's slack";

}  // namespace

std::map<std::string, Reference> brdf_references() {
    std::map<std::string, Reference> all;
    all.emplace("Lambert", make([](const ReferenceContext& c) { return brdf::Lambert{colour(c, "BaseColor")}; }, 1e-4, kWhy));
    all.emplace("PBR", make([](const ReferenceContext& c) {
        return brdf::MetallicRoughness{colour(c, "BaseColor"), c.number("Metallic"), c.number("Roughness")};
    }, 1e-4, kWhy));
    all.emplace("ModifiedPhong", make([](const ReferenceContext& c) {
        return brdf::ModifiedPhong{colour(c, "PhongDiffuse"), c.number("PhongSpecular"), c.number("PhongExponent")};
    }, 1e-4, kWhy));
    all.emplace("CookTorranceBeckmann", make([](const ReferenceContext& c) {
        return brdf::CookTorranceBeckmann{colour(c, "CTDiffuse"), c.number("CTSpecular"), c.number("BeckmannM"), c.number("Eta"),
                                          c.number("PrintedBeckmann") != 0.0};
    }, 1e-4, kWhy));
    all.emplace("AshikhminShirley", make([](const ReferenceContext& c) {
        return brdf::AshikhminShirley{colour(c, "ASDiffuse"), colour(c, "ASSpecular"), c.number("Nu"), c.number("Nv")};
    }, 1e-4, kWhy));
    all.emplace("AshikhminShirleyFit", make([](const ReferenceContext& c) {
        return brdf::AshikhminShirleyFit{colour(c, "FitDiffuse"), colour(c, "FitSpecular"), c.number("FitExponent")};
    }, 1e-4, kWhy));
    return all;
}

}  // namespace fxview::reference
