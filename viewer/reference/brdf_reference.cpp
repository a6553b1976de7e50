// Analytic BRDFs from viewer/brdf (double precision): L = f(l, v) · E · (n·l) at each pixel, with the
// directions built from the captured position, normal and tangent.
#include "reference/brdf_reference.hpp"

#include <algorithm>
#include <cmath>

#include "brdf/models.hpp"
#include "reference/brdf_sensitivity.hpp"

namespace fxview::reference {
namespace {

glm::dvec3 colour(const ReferenceContext& c, const std::string& name) {
    const auto& v = c.values.numbers.at(name);
    return {v.at(0), v.at(1), v.at(2)};
}

template <typename ModelFromParameters>
Reference make(ModelFromParameters model_from, double tolerance, std::string why) {
    Reference r;
    r.shade = [model_from](const ShadingInput& in, const ReferenceContext& c) {
        const glm::dvec3 l = radiance(model_from(c), directions(in), c.number("LightIrradiance"));
        return std::array<double, 4>{l.r, l.g, l.b, 1.0};
    };
    // The tolerance is for radiances of order 1; float's rounding is relative, so above 1 it grows
    // with the pixel's value (a bright light or a white highlight reaches tens).
    r.slack = [model_from, tolerance](const ShadingInput& in, const ReferenceContext& c) {
        const auto model = model_from(c);
        const brdf::Directions d = directions(in);
        const double irradiance = c.number("LightIrradiance");
        const glm::dvec3 value = glm::abs(radiance(model, d, irradiance));
        const double brightest = std::max({value.r, value.g, value.b});
        return tilt_sensitivity(model, d, irradiance) + tolerance * std::max(0.0, brightest - 1.0);
    };
    r.tolerance = tolerance;
    r.why = std::move(why);
    return r;
}

const char* kWhy = "float32 against double on radiances of order 1 (relative above 1): a few ulps of the cosines and of pow/exp (measured "
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
    all.emplace("CookTorranceGGX", make([](const ReferenceContext& c) {
        return brdf::CookTorranceGGX{colour(c, "GGXDiffuse"), colour(c, "GGXF0"), c.number("GGXAlpha")};
    }, 1e-4, kWhy));
    all.emplace("CookTorranceBeckmannSchlick", make([](const ReferenceContext& c) {
        return brdf::CookTorranceBeckmannSchlick{colour(c, "CTSDiffuse"), colour(c, "CTSF0"), c.number("CTSSlope")};
    }, 1e-4, kWhy));
    all.emplace("BlinnPhong", make([](const ReferenceContext& c) {
        return brdf::BlinnPhong{colour(c, "BlinnDiffuse"), colour(c, "BlinnSpecular"), c.number("BlinnExponent")};
    }, 1e-4, kWhy));
    all.emplace("Ward", make([](const ReferenceContext& c) {
        return brdf::Ward{colour(c, "WardDiffuse"), colour(c, "WardSpecular"), c.number("WardAlpha")};
    }, 1e-4, kWhy));
    return all;
}

}  // namespace fxview::reference
