#include "reference/environment_reference.hpp"

#include <algorithm>
#include <cmath>

#include "lighting/image_based_lighting.hpp"

namespace fxview::reference {

std::optional<EnvironmentLookup> EnvironmentLookup::from(const ReferenceContext& c) {
    const render::EnvironmentMaps* maps = c.resources.environment();
    if (!c.environment || c.environment->source.empty() || !maps || maps->empty()) return std::nullopt;
    EnvironmentLookup lookup;
    lookup.maps_ = maps;
    lookup.rotation_ = glm::dmat3(c.environment->world_to_environment());
    lookup.intensity_ = c.environment->intensity;
    return lookup;
}

glm::dvec3 EnvironmentLookup::radiance(const glm::dvec3& world, double roughness, double* seam) const {
    const glm::dvec3 d = rotation_ * world;
    const int last = maps_->specular_data().levels() - 1;
    const double lod = std::clamp(roughness, 0.0, 1.0) * last;
    const int l0 = static_cast<int>(std::floor(lod)), l1 = std::min(l0 + 1, last);
    effect::SamplerState linear;
    linear.min_filter = linear.mag_filter = GL_LINEAR;
    const CubeSample a = sample_cube(maps_->specular_level(l0), linear, false, d), b = sample_cube(maps_->specular_level(l1), linear, false, d);
    if (seam) *seam = std::max(a.seam_spread, b.seam_spread) * intensity_;
    return glm::mix(glm::dvec3(a.value), glm::dvec3(b.value), lod - l0) * intensity_;
}

glm::dvec3 EnvironmentLookup::irradiance(const glm::dvec3& n) const {
    return glm::max(lighting::evaluate_irradiance(maps_->prefiltered().irradiance, rotation_ * n), glm::dvec3(0.0)) * intensity_;
}

glm::dvec2 EnvironmentLookup::dfg(double nv, double roughness) const { return maps_->dfg().lookup(nv, roughness); }

glm::dvec3 metallic_roughness_environment(const EnvironmentLookup& environment, const brdf::Directions& d, const brdf::MetallicRoughness& m,
                                          bool compensation, double* seam) {
    const double nv = glm::dot(d.n, d.v);
    if (nv <= 0.0) return glm::dvec3(0.0);
    const glm::dvec3 f0 = glm::mix(glm::dvec3(0.04), m.base_color, m.metallic);
    const glm::dvec2 ab = environment.dfg(nv, m.roughness);
    const glm::dvec3 scale = compensation ? 1.0 + f0 * (1.0 / std::max(ab.x + ab.y, 1e-4) - 1.0) : glm::dvec3(1.0);
    const glm::dvec3 r = 2.0 * nv * d.n - d.v;  // reflect(-v, n)
    const glm::dvec3 specular = (f0 * ab.x + ab.y) * scale * environment.radiance(r, m.roughness, seam);
    const glm::dvec3 fresnel = f0 + (1.0 - f0) * std::pow(1.0 - nv, 5.0);
    return specular + (1.0 - fresnel) * (1.0 - m.metallic) * m.base_color * environment.irradiance(d.n);
}

}  // namespace fxview::reference
