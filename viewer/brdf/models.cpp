#include "brdf/models.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "brdf/microfacet.hpp"

namespace fxview::brdf {
namespace {

constexpr double kPi = std::numbers::pi;

struct Cosines {
    double nl, nv, nh, vh;
    glm::dvec3 h;
    bool visible;  // both directions above the surface
};

Cosines cosines(const Directions& d) {
    Cosines c{};
    c.nl = glm::dot(d.n, d.l);
    c.nv = glm::dot(d.n, d.v);
    c.visible = c.nl > 0.0 && c.nv > 0.0;
    c.h = glm::normalize(d.l + d.v);
    c.nh = glm::dot(d.n, c.h);
    c.vh = glm::dot(d.v, c.h);
    return c;
}

glm::dvec3 schlick(const glm::dvec3& f0, double cos_theta) {
    return f0 + (1.0 - f0) * std::pow(1.0 - cos_theta, 5.0);
}

}  // namespace

glm::dvec3 evaluate(const Lambert& model, const Directions& d) {
    return cosines(d).visible ? model.albedo / kPi : glm::dvec3(0.0);
}

glm::dvec3 evaluate(const MetallicRoughness& model, const Directions& d) {
    const Cosines c = cosines(d);
    if (!c.visible) return glm::dvec3(0.0);
    const glm::dvec3 f0 = glm::mix(glm::dvec3(0.04), model.base_color, model.metallic);
    const glm::dvec3 fresnel = schlick(f0, std::max(c.vh, 0.0));
    const double alpha = model.roughness * model.roughness;
    const double g = model.correlated_smith ? smith_ggx_correlated(c.nv, c.nl, alpha) : smith_schlick_ggx(c.nv, c.nl, model.roughness);
    const double dg = ggx_distribution(c.nh, alpha) * g;
    const glm::dvec3 kd = (1.0 - fresnel) * (1.0 - model.metallic);
    return kd * model.base_color / kPi + dg * fresnel / (4.0 * c.nl * c.nv);
}

glm::dvec3 evaluate(const ModifiedPhong& model, const Directions& d) {
    const Cosines c = cosines(d);
    if (!c.visible) return glm::dvec3(0.0);
    const glm::dvec3 mirror = 2.0 * c.nl * d.n - d.l;  // l reflected about n
    const double lobe = std::pow(std::max(glm::dot(mirror, d.v), 0.0), model.exponent);
    return model.kd / kPi + model.ks * (model.exponent + 2.0) / (2.0 * kPi) * lobe;
}

glm::dvec3 evaluate(const CookTorranceBeckmann& model, const Directions& d) {
    const Cosines c = cosines(d);
    if (!c.visible) return glm::dvec3(0.0);
    const double D = beckmann_distribution(c.nh, model.m, model.printed_beckmann);
    const double G = v_cavity_geometry(c.nh, c.nv, c.nl, c.vh);
    const double F = fresnel_dielectric(model.eta, c.vh);
    return model.kd / kPi + model.ks * D * G * F / (4.0 * c.nl * c.nv);
}

glm::dvec3 evaluate(const AshikhminShirley& model, const Directions& d) {
    const Cosines c = cosines(d);
    if (!c.visible) return glm::dvec3(0.0);
    const auto grazing = [](double x) { return 1.0 - std::pow(1.0 - x / 2.0, 5.0); };
    const glm::dvec3 diffuse = 28.0 / (23.0 * kPi) * model.rd * (1.0 - model.rs) * grazing(c.nl) * grazing(c.nv);
    // Exponent nu cos²φ + nv sin²φ from h's components along t and n × t; at h = n φ is undefined
    // and (n·h)^anything = 1.
    const double hu = glm::dot(c.h, d.t), hv = glm::dot(c.h, glm::cross(d.n, d.t));
    const double tangential = hu * hu + hv * hv;
    const double exponent = tangential > 0.0 ? (model.nu * hu * hu + model.nv * hv * hv) / tangential : 0.0;
    const double lobe = std::sqrt((model.nu + 1.0) * (model.nv + 1.0)) / (8.0 * kPi) * std::pow(c.nh, exponent) /
                        (c.vh * std::max(c.nl, c.nv));
    return diffuse + lobe * schlick(model.rs, c.vh);
}

glm::dvec3 evaluate(const AshikhminShirleyFit& model, const Directions& d) {
    const Cosines c = cosines(d);
    if (!c.visible) return glm::dvec3(0.0);
    const double lobe = (model.ns + 1.0) / (8.0 * kPi) * std::pow(c.nh, model.ns) / (c.vh * std::max(c.nl, c.nv));
    return model.cd / kPi + lobe * model.cs;
}

double smith_ggx_correlated(double n_dot_l, double n_dot_v, double alpha) {
    const auto lambda = [alpha](double x) { return 0.5 * (std::sqrt(1.0 + alpha * alpha * (1.0 - x * x) / (x * x)) - 1.0); };
    return 1.0 / (1.0 + lambda(n_dot_l) + lambda(n_dot_v));
}

glm::dvec3 evaluate(const CookTorranceGGX& model, const Directions& d) {
    const Cosines c = cosines(d);
    if (!c.visible) return glm::dvec3(0.0);
    const double dg = ggx_distribution(c.nh, model.alpha) * smith_ggx_correlated(c.nl, c.nv, model.alpha);
    return model.kd / kPi + dg / (4.0 * c.nl * c.nv) * schlick(model.f0, std::max(c.vh, 0.0));
}

glm::dvec3 evaluate(const CookTorranceBeckmannSchlick& model, const Directions& d) {
    const Cosines c = cosines(d);
    if (!c.visible) return glm::dvec3(0.0);
    const double dg = beckmann_distribution(c.nh, model.m) * v_cavity_geometry(c.nh, c.nv, c.nl, c.vh);
    return model.kd / kPi + dg / (4.0 * c.nl * c.nv) * schlick(model.f0, std::max(c.vh, 0.0));
}

glm::dvec3 evaluate(const BlinnPhong& model, const Directions& d) {
    const Cosines c = cosines(d);
    if (!c.visible) return glm::dvec3(0.0);
    return model.kd / kPi + model.ks * (model.exponent + 8.0) / (8.0 * kPi) * std::pow(std::max(c.nh, 0.0), model.exponent);
}

glm::dvec3 evaluate(const Ward& model, const Directions& d) {
    const Cosines c = cosines(d);
    if (!c.visible) return glm::dvec3(0.0);
    const double a2 = model.alpha * model.alpha, cos2 = c.nh * c.nh;
    const double tan2 = (1.0 - cos2) / cos2;
    return model.kd / kPi + model.ks * std::exp(-tan2 / a2) / (4.0 * kPi * a2 * std::sqrt(c.nl * c.nv));
}

}  // namespace fxview::brdf
