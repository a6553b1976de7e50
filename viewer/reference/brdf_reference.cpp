// Analytic BRDFs from viewer/brdf (double precision): L = f(l, v) · E · (n·l) at each pixel, with the
// directions built from the captured position, normal and tangent.
#include "reference/brdf_reference.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <functional>
#include <optional>


#include "brdf/direction_sampling.hpp"
#include "brdf/models.hpp"
#include "reference/area_light_brdf.hpp"
#include "reference/brdf_sensitivity.hpp"
#include "reference/environment_reference.hpp"

namespace fxview::reference {
namespace {

glm::dvec3 colour(const ReferenceContext& c, const std::string& name) {
    const auto& v = c.values.numbers.at(name);
    return {v.at(0), v.at(1), v.at(2)};
}

template <typename ModelFromParameters>
Reference make(ModelFromParameters model_from, std::function<double(const ReferenceContext&)> alpha_from, double tolerance, std::string why) {
    // f(l, v) of the model for the pixel's eye and frame, towards any l (a sized light's directions).
    const auto towards = [model_from](const ReferenceContext& c, const brdf::Directions& d) {
        return [model = model_from(c), d](const glm::dvec3& l) {
            brdf::Directions at = d;
            at.l = l;
            return brdf::evaluate(model, at);
        };
    };
    Reference r;
    r.shade = [model_from, alpha_from, towards](const ShadingInput& in, const ReferenceContext& c) {
        const brdf::Directions d = directions(in);
        const glm::dvec3 l = light_is_sized(in) ? c.number("LightIrradiance") * area_light_brdf(in, d, towards(c, d), alpha_from(c))
                                                : radiance(model_from(c), d, c.number("LightIrradiance"));
        return std::array<double, 4>{l.r, l.g, l.b, 1.0};
    };
    // The tolerance is for radiances of order 1; float's rounding is relative, so above 1 it grows
    // with the pixel's value (a bright light or a white highlight reaches tens). Under a sized light
    // the lobe directions that pass within float's reach of its outline may count or not.
    r.slack = [model_from, alpha_from, towards, tolerance](const ShadingInput& in, const ReferenceContext& c) {
        const auto model = model_from(c);
        const brdf::Directions d = directions(in);
        const double irradiance = c.number("LightIrradiance");
        if (light_is_sized(in)) {
            // A sharp lobe amplifies float's rounding of each direction's cosines (~1e-7) by its exponent,
            // about 2/α² for a GGX width α, and a light close by that of the position: that part may move.
            double edge = 0;
            const glm::dvec3 value = glm::abs(irradiance * area_light_brdf(in, d, towards(c, d), alpha_from(c), &edge));
            const double alpha = std::clamp(alpha_from(c), 0.001, 1.0), brightest = std::max({value.r, value.g, value.b});
            return irradiance * edge + brightest * (1e-7 * 2.0 / (alpha * alpha) + near_light_rounding(in)) + tolerance * std::max(0.0, brightest - 1.0);
        }
        const glm::dvec3 value = glm::abs(radiance(model, d, irradiance));
        const double brightest = std::max({value.r, value.g, value.b});
        return tilt_sensitivity(model, d, irradiance) + tolerance * std::max(0.0, brightest - 1.0);
    };
    // Under a sized light, `compare --ground-truth` measures the estimate against the integral over the light.
    r.truth = [model_from, alpha_from, towards](const ShadingInput& in, const ReferenceContext& c, unsigned) {
        const brdf::Directions d = directions(in);
        const glm::dvec3 l = light_is_sized(in) ? c.number("LightIrradiance") * area_light_brdf_integral(in, d, towards(c, d), std::clamp(alpha_from(c), 0.001, 1.0))
                                                : radiance(model_from(c), d, c.number("LightIrradiance"));
        return std::array<double, 4>{l.r, l.g, l.b, 1.0};
    };
    r.truth_method = "the integral over the light (midpoint rules over its surface and about the mirror direction)";
    r.truth_with_sized_light = true;
    r.truth_deterministic_without_environment = true;
    r.tolerance = tolerance;
    r.why = std::move(why);
    return r;
}

const char* kWhy = "float32 against double on radiances of order 1 (relative above 1): a few ulps of the cosines and of pow/exp (measured "
                   "on llvmpipe below 3e-5 outside highlights); in highlights, where moving n.h by its float "
                   "rounding (2.4e-7) moves the radiance by more, that change is the pixel's slack";

// Each model from the effect's parameters (analytic.fx), shared by the techniques' references and
// the direction grid's.
brdf::Lambert lambert(const ReferenceContext& c) { return brdf::Lambert{colour(c, "BaseColor")}; }
brdf::MetallicRoughness pbr(const ReferenceContext& c) {
    return brdf::MetallicRoughness{colour(c, "BaseColor"), c.number("Metallic"), c.number("Roughness")};
}
brdf::ModifiedPhong modified_phong(const ReferenceContext& c) {
    return brdf::ModifiedPhong{colour(c, "PhongDiffuse"), c.number("PhongSpecular"), c.number("PhongExponent")};
}
brdf::CookTorranceBeckmann cook_torrance_beckmann(const ReferenceContext& c) {
    return brdf::CookTorranceBeckmann{colour(c, "CTDiffuse"), c.number("CTSpecular"), c.number("BeckmannM"), c.number("Eta"),
                                      c.number("PrintedBeckmann") != 0.0};
}
brdf::AshikhminShirley ashikhmin_shirley(const ReferenceContext& c) {
    return brdf::AshikhminShirley{colour(c, "ASDiffuse"), colour(c, "ASSpecular"), c.number("Nu"), c.number("Nv")};
}
brdf::AshikhminShirleyFit ashikhmin_shirley_fit(const ReferenceContext& c) {
    return brdf::AshikhminShirleyFit{colour(c, "FitDiffuse"), colour(c, "FitSpecular"), c.number("FitExponent")};
}
brdf::CookTorranceGGX cook_torrance_ggx(const ReferenceContext& c) {
    return brdf::CookTorranceGGX{colour(c, "GGXDiffuse"), colour(c, "GGXF0"), c.number("GGXAlpha")};
}
brdf::CookTorranceBeckmannSchlick cook_torrance_beckmann_schlick(const ReferenceContext& c) {
    return brdf::CookTorranceBeckmannSchlick{colour(c, "CTSDiffuse"), colour(c, "CTSF0"), c.number("CTSSlope")};
}
brdf::BlinnPhong blinn_phong(const ReferenceContext& c) {
    return brdf::BlinnPhong{colour(c, "BlinnDiffuse"), colour(c, "BlinnSpecular"), c.number("BlinnExponent")};
}
brdf::Ward ward(const ReferenceContext& c) { return brdf::Ward{colour(c, "WardDiffuse"), colour(c, "WardSpecular"), c.number("WardAlpha")}; }

// f of the model BrdfModel names (its UIItems order), 0 where the light or the eye is below the surface.
glm::dvec3 grid_model_value(const ReferenceContext& c, const brdf::Directions& d) {
    if (glm::dot(d.n, d.l) <= 0.0 || glm::dot(d.n, d.v) <= 0.0) return glm::dvec3(0.0);
    switch (static_cast<int>(c.number("BrdfModel"))) {
        case 0: return brdf::evaluate(lambert(c), d);
        case 1: return brdf::evaluate(pbr(c), d);
        case 2: return brdf::evaluate(modified_phong(c), d);
        case 3: return brdf::evaluate(cook_torrance_beckmann(c), d);
        case 4: return brdf::evaluate(ashikhmin_shirley(c), d);
        case 5: return brdf::evaluate(ashikhmin_shirley_fit(c), d);
        case 6: return brdf::evaluate(cook_torrance_ggx(c), d);
        case 7: return brdf::evaluate(cook_torrance_beckmann_schlick(c), d);
        case 8: return brdf::evaluate(blinn_phong(c), d);
        default: return brdf::evaluate(ward(c), d);
    }
}

// The directions of a pixel of the grid (effects/lib/brdf_grid.glsl), from the captured fragment
// position and viewport size; empty where the grid draws 0 (tiles past the last incidence, the
// slice below the surface).
std::optional<brdf::Directions> grid_directions(const ShadingInput& in, const ReferenceContext& c) {
    const double fx = in.footprint.x, fy = in.footprint.y, width = in.footprint.z, height = in.footprint.w;
    const auto radians = [](double degrees) { return degrees * std::numbers::pi / 180.0; };
    brdf::Directions d{{0, 0, 1}, {}, {}, {1, 0, 0}};
    switch (static_cast<int>(c.number("FxGridMode"))) {
        case 1: {
            const double to = radians(-90.0 + 180.0 * fx / width), pi = radians(c.number("FxPhiI"));
            d.l = brdf::incident_direction(c.number("FxIncidence"), c.number("FxPhiI"));
            d.v = {std::sin(to) * std::cos(pi), std::sin(to) * std::sin(pi), std::cos(to)};
            break;
        }
        case 2: {
            const double th = radians(90.0 * fx / width), td = radians(90.0 * fy / height), pd = radians(c.number("FxPhiD"));
            const glm::dvec3 diff(std::sin(td) * std::cos(pd), std::sin(td) * std::sin(pd), std::cos(td));
            d.l = {diff.x * std::cos(th) + diff.z * std::sin(th), diff.y, -diff.x * std::sin(th) + diff.z * std::cos(th)};
            const glm::dvec3 h(std::sin(th), 0, std::cos(th));
            d.v = 2.0 * glm::dot(d.l, h) * h - d.l;
            if (d.l.z <= 0 || d.v.z <= 0) return std::nullopt;
            break;
        }
        case 3: {
            const double phi = radians(360.0 * fx / width), to = radians(90.0 * fy / height);
            d.l = brdf::incident_direction(c.number("FxIncidence"), c.number("FxPhiI"));
            d.v = {std::sin(to) * std::cos(phi), std::sin(to) * std::sin(phi), std::cos(to)};
            break;
        }
        case 4: {  // brdf-check's sample directions (brdf/direction_sampling.hpp)
            const int side = static_cast<int>(width) / 9, px = static_cast<int>(fx), py = static_cast<int>(fy), tile = (py / side) * 9 + px / side;
            if (tile >= 45) return std::nullopt;
            const auto strategy = static_cast<int>(c.number("FxSampleStrategy"));
            brdf::SampleSet set;
            set.strategy = static_cast<brdf::SamplingStrategy>(std::clamp(strategy, 0, 2));
            set.alpha = c.number("FxSampleAlpha");
            const std::vector<double>& shift = c.values.numbers.at("FxSampleShift");
            set.shift = {shift.at(0), shift.at(1)};
            set.phi_i_degrees = c.number("FxPhiI");
            set.side = static_cast<int>(c.number("FxSampleSide"));
            if (px % side >= set.side || py % side >= set.side) return std::nullopt;
            d.l = brdf::incident_direction(1.0 + 2.0 * tile, set.phi_i_degrees);
            d.v = brdf::sampled_direction(set, d.l, px % side, py % side);
            if (d.v.z <= 0) return std::nullopt;
            d.v = glm::normalize(d.v);
            break;
        }
        default: {
            const int px = static_cast<int>(fx), py = static_cast<int>(fy), tile = (py / 256) * 9 + px / 256;
            if (tile >= 45) return std::nullopt;
            const double mu = (py % 256 + 0.5) / 256.0, phi = 2.0 * std::numbers::pi * (px % 256 + 0.5) / 256.0;
            const double s = std::sqrt(std::max(1.0 - mu * mu, 0.0));
            d.l = brdf::incident_direction(1.0 + 2.0 * tile, c.number("FxPhiI"));
            d.v = {s * std::cos(phi), s * std::sin(phi), mu};
        }
    }
    if (c.number("FxSwapArguments") != 0.0) std::swap(d.l, d.v);
    return d;
}

Reference grid_reference() {
    Reference r;
    r.shade = [](const ShadingInput& in, const ReferenceContext& c) {
        const auto d = grid_directions(in, c);
        const glm::dvec3 f = d ? grid_model_value(c, *d) : glm::dvec3(0.0);
        return std::array<double, 4>{f.r, f.g, f.b, 1.0};
    };
    // In float, n·h near 1 is known to ~2.4e-7 only, and the directions come from float sines and
    // cosines: where f is steep (sharp lobes, grazing 1/(n.l n.v) terms) that moves it by more than the
    // tolerance. The slack is the change when the normal tilts by that uncertainty (brdf_sensitivity.hpp),
    // plus 1e-3 of values above 1: the lobes reach f ~ 1e4, where the dot products behind the exponent
    // (r·v for Phong, h's azimuth for anisotropic lobes) carry ~10 float roughings each, and an
    // exponent of 1e4 turns 1e-7 into 1e-3 (measured up to 4e-4 relative on llvmpipe).
    r.slack = [](const ShadingInput& in, const ReferenceContext& c) {
        const auto d = grid_directions(in, c);
        if (!d) return 0.0;
        const glm::dvec3 base = grid_model_value(c, *d);
        return tilt_spread([&](const brdf::Directions& at) { return grid_model_value(c, at); }, *d) +
               1e-3 * std::max(0.0, std::max({std::abs(base.r), std::abs(base.g), std::abs(base.b)}) - 1.0);
    };
    r.tolerance = 1e-4;
    r.why = "the BRDF itself (no light) in float against double; slack: the change when the normal tilts by the float "
            "uncertainty of n.h, plus 1e-3 of values above 1 (lobes up to f ~ 1e4 from float dot products under high exponents)";
    return r;
}

// A technique that adds the scene environment's light (environment.glsl) to the point light's.
// Tolerance of that term: the GPU's bilinear weights and cube-map texel addressing are computed with
// limited precision (GL allows fixed-point weights; 8 fractional bits give 1/512 of the step between
// neighbouring texels), so the environment term gets 1e-3 of its value (at least of 1) as slack,
// a quarter of one 8-bit code value at display white; plus, at cube corners, the spread of the
// texels GL leaves to the implementation.
using EnvironmentTerm = std::function<glm::dvec3(const EnvironmentLookup&, const brdf::Directions&, const ReferenceContext&, double* seam)>;
using EnvironmentTruth = std::function<glm::dvec3(const EnvironmentLookup&, const brdf::Directions&, const ReferenceContext&, unsigned seed)>;

// Directions enough that the Monte Carlo's own error (cosine/GGX mixture, balance heuristic) stays
// well below the split sum's on smooth environments; the sun is integrated apart.
constexpr int kTruthSamples = 4096;

Reference with_environment(Reference point_light, EnvironmentTerm term, EnvironmentTruth truth) {
    const Shader shade = point_light.shade;
    point_light.shade = [shade, term](const ShadingInput& in, const ReferenceContext& c) {
        std::array<double, 4> value = shade(in, c);
        if (const auto environment = EnvironmentLookup::from(c)) {
            const glm::dvec3 e = term(*environment, directions(in), c, nullptr);
            for (int k = 0; k < 3; ++k) value[static_cast<size_t>(k)] += e[k];
        }
        return value;
    };
    const auto slack = point_light.slack;
    point_light.slack = [slack, term](const ShadingInput& in, const ReferenceContext& c) {
        double total = slack ? slack(in, c) : 0.0;
        if (const auto environment = EnvironmentLookup::from(c)) {
            double seam = 0.0;
            const glm::dvec3 e = glm::abs(term(*environment, directions(in), c, &seam));
            total += seam + 1e-3 * std::max({1.0, e.r, e.g, e.b});
        }
        return total;
    };
    point_light.truth = [light = point_light.truth, truth](const ShadingInput& in, const ReferenceContext& c, unsigned seed) {
        std::array<double, 4> value = light(in, c, seed);
        if (const auto environment = EnvironmentLookup::from(c)) {
            const glm::dvec3 e = truth(*environment, directions(in), c, seed);
            for (int k = 0; k < 3; ++k) value[static_cast<size_t>(k)] += e[k];
        }
        return value;
    };
    point_light.why += "; the environment's light: 1e-3 of it (the GPU's bilinear weights), plus the texel spread at cube corners";
    return point_light;
}

glm::dvec3 lambert_environment(const EnvironmentLookup& environment, const brdf::Directions& d, const ReferenceContext& c, double*) {
    return lambert(c).albedo * environment.irradiance(environment_facing(d).n);
}

glm::dvec3 pbr_environment(const EnvironmentLookup& environment, const brdf::Directions& d, const ReferenceContext& c, double* seam) {
    return metallic_roughness_environment(environment, d, pbr(c), c.number("EnergyCompensation") != 0.0, c.number("LobeSampling") != 0.0, seam);
}

glm::dvec3 lambert_truth(const EnvironmentLookup& environment, const brdf::Directions& d, const ReferenceContext& c, unsigned seed) {
    const glm::dvec3 albedo = lambert(c).albedo;
    return environment.integral(d, [&](const glm::dvec3&) { return albedo / std::numbers::pi; }, 1.0, kTruthSamples, seed);
}

glm::dvec3 pbr_truth(const EnvironmentLookup& environment, const brdf::Directions& d, const ReferenceContext& c, unsigned seed) {
    brdf::MetallicRoughness model = pbr(c);
    model.correlated_smith = true;  // under image-based light the BRDF's masking is the DFG table's
    const bool compensation = c.number("EnergyCompensation") != 0.0;
    const auto f = [&](const glm::dvec3& l) {
        brdf::Directions at = environment_facing(d);
        at.l = l;
        return metallic_roughness_compensated(environment, at, model, compensation);
    };
    return environment.integral(d, f, std::max(model.roughness * model.roughness, 1e-3), kTruthSamples, seed);
}

// A model lit by the environment through environment_light.glsl's filtered importance sampling
// (`alpha_from`: the sampled GGX width the technique passes), and its ground truth.
template <typename ModelFrom, typename AlphaFrom>
Reference sampled_environment(ModelFrom model_from, AlphaFrom alpha_from) {
    const auto value_towards = [model_from](const ReferenceContext& c, const brdf::Directions& d) {
        return [model = model_from(c), d](const glm::dvec3& l) {
            brdf::Directions at = environment_facing(d);  // as environment_light.glsl shades a silhouette
            at.l = l;
            return brdf::evaluate(model, at);
        };
    };
    const auto alpha = [alpha_from](const ReferenceContext& c) { return std::clamp(alpha_from(c), 0.001, 1.0); };
    return with_environment(
        make(model_from, alpha, 1e-4, kWhy),
        [value_towards, alpha](const EnvironmentLookup& environment, const brdf::Directions& d, const ReferenceContext& c, double* seam) {
            return environment.light(d, value_towards(c, d), alpha(c), seam);
        },
        [value_towards, alpha](const EnvironmentLookup& environment, const brdf::Directions& d, const ReferenceContext& c, unsigned seed) {
            return environment.integral(d, value_towards(c, d), alpha(c), kTruthSamples, seed);
        });
}

}  // namespace

std::map<std::string, Reference> brdf_references() {
    std::map<std::string, Reference> all;
    all.emplace("Lambert", with_environment(make(lambert, [](const ReferenceContext&) { return 1.0; }, 1e-4, kWhy), lambert_environment, lambert_truth));
    all.emplace("PBR", with_environment(make(pbr, [](const ReferenceContext& c) { return std::pow(c.number("Roughness"), 2.0); }, 1e-4, kWhy),
                                        pbr_environment, pbr_truth));
    // The sampled GGX widths environment_light() gets in analytic.fx: a lobe of similar size (Walter's
    // Blinn-Phong correspondence, the Phong lobe about r being about four times the exponent about h).
    all.emplace("ModifiedPhong", sampled_environment(modified_phong, [](const ReferenceContext& c) { return std::sqrt(2.0 / (4.0 * c.number("PhongExponent") + 2.0)); }));
    all.emplace("CookTorranceBeckmann", sampled_environment(cook_torrance_beckmann, [](const ReferenceContext& c) { return c.number("BeckmannM"); }));
    all.emplace("AshikhminShirley", sampled_environment(ashikhmin_shirley, [](const ReferenceContext& c) {
                    return std::sqrt(2.0 / (std::sqrt(c.number("Nu") * c.number("Nv")) + 2.0));
                }));
    all.emplace("AshikhminShirleyFit", sampled_environment(ashikhmin_shirley_fit, [](const ReferenceContext& c) { return std::sqrt(2.0 / (c.number("FitExponent") + 2.0)); }));
    all.emplace("CookTorranceGGX", sampled_environment(cook_torrance_ggx, [](const ReferenceContext& c) { return c.number("GGXAlpha"); }));
    all.emplace("CookTorranceBeckmannSchlick", sampled_environment(cook_torrance_beckmann_schlick, [](const ReferenceContext& c) { return c.number("CTSSlope"); }));
    all.emplace("BlinnPhong", sampled_environment(blinn_phong, [](const ReferenceContext& c) { return std::sqrt(2.0 / (c.number("BlinnExponent") + 2.0)); }));
    all.emplace("Ward", sampled_environment(ward, [](const ReferenceContext& c) { return c.number("WardAlpha"); }));
    all.emplace("BrdfGrid", grid_reference());
    return all;
}


}  // namespace fxview::reference
