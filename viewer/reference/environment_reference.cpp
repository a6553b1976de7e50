#include "reference/environment_reference.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "brdf/microfacet.hpp"
#include "lighting/image_based_lighting.hpp"
#include "lighting/lobe_mass.hpp"
#include "reference/tangent_frame.hpp"

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
    const double lod = lighting::prefiltered_lod(roughness, last + 1);
    const int l0 = static_cast<int>(std::floor(lod)), l1 = std::min(l0 + 1, last);
    effect::SamplerState linear;
    linear.min_filter = linear.mag_filter = GL_LINEAR;
    const CubeSample a = sample_cube(maps_->specular_level(l0), linear, false, d), b = sample_cube(maps_->specular_level(l1), linear, false, d);
    if (seam) *seam = std::max(a.seam_spread, b.seam_spread) * intensity_;
    return glm::mix(glm::dvec3(a.value), glm::dvec3(b.value), lod - l0) * intensity_;
}

glm::dvec3 EnvironmentLookup::lobe_radiance(const glm::dvec3& n, const glm::dvec3& v, const glm::dvec3& f0, double roughness, double* seam) const {
    constexpr int kSamples = 16;
    const double alpha = std::max(roughness * roughness, 1e-4), nv = std::max(glm::dot(n, v), 1e-4);
    glm::dvec3 x, y;
    duff_frame(n, x, y);
    glm::dvec3 sum(0.0), total(0.0);
    double spread = 0.0;
    for (int i = 0; i < kSamples; ++i) {
        const glm::dvec2 u = lighting::hammersley(static_cast<unsigned>(i), kSamples);
        const glm::dvec3 hl = lighting::sample_ggx(u.x, u.y, alpha);
        const glm::dvec3 h = hl.x * x + hl.y * y + hl.z * n;
        const double vh = glm::dot(v, h);
        const glm::dvec3 l = 2.0 * vh * h - v;
        const double nl = glm::dot(n, l);
        if (nl <= 0.0 || vh <= 0.0) continue;
        const double pdf = lighting::ggx_d(hl.z, alpha) * hl.z / (4.0 * vh);
        const double share = 1.0 / (kSamples * pdf);
        const glm::dvec3 weight = (f0 + (1.0 - f0) * std::pow(std::clamp(1.0 - vh, 0.0, 1.0), 5.0)) * (brdf::smith_ggx_correlated(nl, nv, alpha) * vh / hl.z);
        double seam_here = 0.0;
        sum += weight * radiance(l, std::sqrt(std::clamp(std::sqrt(share / (4.0 * std::numbers::pi)), 0.0, 1.0)), &seam_here);
        total += weight;
        spread = std::max(spread, seam_here);
    }
    if (seam) *seam = spread;
    if (!(total.r + total.g + total.b > 0.0)) return radiance(2.0 * glm::dot(n, v) * n - v, roughness, seam);
    return sum / glm::max(total, glm::dvec3(1e-30));
}

glm::dvec3 EnvironmentLookup::irradiance(const glm::dvec3& n) const {
    return lighting::evaluate_irradiance(maps_->prefiltered(), rotation_ * n) * intensity_;
}

glm::dvec3 EnvironmentLookup::map_irradiance(const glm::dvec3& n) const {
    return glm::max(lighting::evaluate_irradiance(maps_->prefiltered().irradiance, rotation_ * n), glm::dvec3(0.0)) * intensity_;
}

glm::dvec3 EnvironmentLookup::dfg(double nv, double roughness) const { return maps_->dfg().lookup(nv, roughness); }

glm::dvec3 EnvironmentLookup::spectral_weights(const glm::dvec3& world, double* seam) const {
    effect::SamplerState linear;
    linear.min_filter = linear.mag_filter = GL_LINEAR;
    const CubeSample w = sample_cube(maps_->spectral_weights_data(), linear, false, rotation_ * world);
    if (seam) *seam = w.seam_spread * intensity_;
    return glm::dvec3(w.value) * intensity_;
}

double EnvironmentLookup::spectral_radiance(const glm::dvec3& weights, int nm) const {
    const auto& spectra = maps_->unfiltered().spectral->spectra;
    const size_t i = static_cast<size_t>(nm - lighting::SpectralForm::kFirstNm);
    double sum = 0;
    for (size_t k = 0; k < 3; ++k) sum += weights[static_cast<int>(k)] * static_cast<double>(static_cast<float>(spectra[k][i]));
    return sum;
}

glm::dvec3 EnvironmentLookup::exact_spectral_weights(const glm::dvec3& world) const {
    const lighting::SpectralForm& form = *maps_->unfiltered().spectral;
    if (!form.texels_only) return form.exact(rotation_ * world) * intensity_;
    effect::SamplerState linear;
    linear.min_filter = linear.mag_filter = GL_LINEAR;
    const glm::dvec3 d = glm::normalize(rotation_ * world);
    glm::dvec3 w(sample_cube(maps_->spectral_lobe_level(0), linear, false, d).value);
    for (const lighting::DiscLight& disc : form.discs)
        if (glm::dot(d, disc.direction) > std::cos(disc.angular_radius)) w += disc.radiance;
    return w * intensity_;
}

double EnvironmentLookup::exact_spectral_radiance(const glm::dvec3& weights, int nm) const {
    if (const auto& uplifted = maps_->unfiltered().spectral->exact_radiance) return uplifted(weights, nm);
    const auto& spectra = maps_->unfiltered().spectral->spectra;
    const size_t i = static_cast<size_t>(nm - lighting::SpectralForm::kFirstNm);
    return weights.x * spectra[0][i] + weights.y * spectra[1][i] + weights.z * spectra[2][i];
}

glm::dvec3 EnvironmentLookup::spectral_irradiance(const glm::dvec3& n, double* seam) const {
    effect::SamplerState linear;
    linear.min_filter = linear.mag_filter = GL_LINEAR;
    const CubeSample w = sample_cube(maps_->spectral_irradiance_data(), linear, false, rotation_ * n);
    if (seam) *seam = (w.seam_spread + w.footprint_spread / 256.0) * intensity_;
    return glm::dvec3(w.value) * intensity_;
}

glm::dvec3 EnvironmentLookup::spectral_filtered(const glm::dvec3& world, double share, double* seam) const {
    constexpr double kPi = std::numbers::pi;
    effect::SamplerState linear;
    linear.min_filter = linear.mag_filter = GL_LINEAR;
    // As the GPU: no level coarser than 8² a face (every texel of a smaller one touches a corner).
    const double size = maps_->spectral_lobe_level(0).width();
    const double last = std::min<double>(maps_->spectral_lobe_levels() - 1, std::max(std::log2(size / 8.0), 0.0));
    const double lod = std::clamp(0.5 * std::log2(share * 6.0 * size * size / (4.0 * kPi)) + 1.0, 0.0, last), low = std::floor(lod);
    const glm::dvec3 d = rotation_ * world;
    const CubeSample p = sample_cube(maps_->spectral_lobe_level(static_cast<int>(low)), linear, false, d);
    const CubeSample q = sample_cube(maps_->spectral_lobe_level(static_cast<int>(std::min(low + 1.0, last))), linear, false, d);
    const double mixed = lod - low;
    if (seam) *seam = std::max(p.seam_spread, q.seam_spread) + ((1.0 - mixed) * p.footprint_spread + mixed * q.footprint_spread) / 256.0;
    return glm::mix(glm::dvec3(p.value), glm::dvec3(q.value), mixed) * intensity_;
}

std::vector<EnvironmentLookup::DiscPoint> EnvironmentLookup::spectral_disc_points() const {
    // 16 points of equal area over each disc (a sunflower spiral), placed in environment space as the GPU does.
    const double golden = std::numbers::pi * (3.0 - std::sqrt(5.0));
    const glm::dmat3 to_world = glm::transpose(rotation_);
    std::vector<DiscPoint> points;
    for (const lighting::DiscLight& disc : maps_->unfiltered().spectral->discs) {
        glm::dvec3 dx, dy;
        duff_frame(disc.direction, dx, dy);
        for (int j = 0; j < 16; ++j) {
            const double r = std::sqrt((j + 0.5) / 16.0) * disc.angular_radius, angle = golden * j;
            const glm::dvec3 l = glm::normalize(disc.direction + std::tan(r) * (std::cos(angle) * dx + std::sin(angle) * dy));
            points.push_back({to_world * l, disc.radiance * disc.solid_angle() / 16.0 / std::numbers::pi * intensity_, disc.angular_radius});
        }
    }
    return points;
}

glm::dvec2 EnvironmentLookup::spectral_lobe_mass(double nv, double power) const {
    return glm::dvec2(maps_->lobe_mass().lookup(nv, lighting::lobe_mass_row(power))) * lighting::lobe_mass_unit(power);
}

glm::dvec3 EnvironmentLookup::spectral_highlight(const glm::dvec3& n, const glm::dvec3& v, bool blinn, double power, double* seam) const {
    const int samples = power >= 64.0 ? 32 : power >= 8.0 ? 64 : 256;  // spectral_lobe_samples()
    constexpr double kPi = std::numbers::pi;
    const glm::dvec3 axis = blinn ? n : 2.0 * glm::dot(n, v) * n - v;
    glm::dvec3 x, y;
    duff_frame(axis, x, y);
    glm::dvec3 sum(0.0);
    double spread = 0.0, total = 0.0;
    for (int i = 0; i < samples; ++i) {
        const glm::dvec2 u = lighting::hammersley(static_cast<unsigned>(i), samples);
        const double cosine = std::pow(1.0 - u.x, 1.0 / (power + 1.0)), sine = std::sqrt(std::max(0.0, 1.0 - cosine * cosine));
        const glm::dvec3 direction = sine * std::cos(2.0 * kPi * u.y) * x + sine * std::sin(2.0 * kPi * u.y) * y + cosine * axis;
        double density = (power + 1.0) / (2.0 * kPi) * std::pow(cosine, power), weight = 1.0;
        glm::dvec3 l = direction;
        if (blinn) {
            const double vh = glm::dot(v, direction);
            if (vh <= 0.0) continue;
            l = 2.0 * vh * direction - v;
            density /= 4.0 * vh;
            weight = 4.0 * vh;
        }
        if (glm::dot(n, l) <= 0.0 || !(density > 0.0)) continue;
        double seam_here = 0.0;
        sum += weight * spectral_filtered(l, 1.0 / (samples * density), &seam_here);
        spread += weight * seam_here;
        total += weight;
    }
    // The lobe's mass above the surface (the table, as the GPU samples it) times the mean under it.
    const glm::dvec2 mass = spectral_lobe_mass(glm::dot(n, v), power);
    const double scale = total > 0.0 ? (blinn ? mass.y : mass.x) / total : 0.0;
    if (seam) *seam = spread * scale * intensity_;
    const glm::dvec3 r = 2.0 * glm::dot(n, v) * n - v;
    glm::dvec3 discs(0.0);
    for (const DiscPoint& point : spectral_disc_points()) {
        if (glm::dot(n, point.direction) <= 0.0) continue;
        discs += point.weights * std::pow(std::max(blinn ? glm::dot(n, glm::normalize(point.direction + v)) : glm::dot(r, point.direction), 0.0), power);
    }
    return sum * scale + discs;
}

void EnvironmentLookup::visit_exact_integral(const std::function<double(const glm::dvec3&)>& g, const Draw& draw, int samples, unsigned seed,
                                             const std::function<void(double factor, const glm::dvec3& l)>& add) const {
    const glm::dmat3 to_world = glm::transpose(rotation_);
    const auto& discs = maps_->unfiltered().discs;
    const auto in_disc = [&](const glm::dvec3& l) {
        for (const lighting::DiscLight& disc : discs)
            if (glm::dot(l, to_world * disc.direction) >= std::cos(disc.angular_radius)) return true;
        return false;
    };
    // The Hammersley set turned per pixel (Cranley-Patterson rotation by the seed's two numbers).
    const double shift_u = (seed % 9973u) / 9973.0, shift_v = (seed / 9973u % 9967u) / 9967.0;
    for (int i = 0; i < samples; ++i) {
        const glm::dvec2 h = lighting::hammersley(static_cast<unsigned>(i), static_cast<unsigned>(samples));
        double density = 0.0;
        const glm::dvec3 l = draw({std::fmod(h.x + shift_u, 1.0), std::fmod(h.y + shift_v, 1.0)}, density);
        if (!(density > 0.0) || in_disc(l)) continue;
        const double value = g(l);
        if (value != 0.0) add(value / density / static_cast<double>(samples) / std::numbers::pi, l);
    }
    for (const lighting::DiscLight& disc : discs) {
        const std::vector<glm::dvec3> points = disc.quadrature(to_world * disc.direction);
        for (const glm::dvec3& l : points) add(g(l) * disc.solid_angle() / static_cast<double>(points.size()) / std::numbers::pi, l);
    }
}

glm::dvec3 EnvironmentLookup::exact_spectral_integral(const std::function<double(const glm::dvec3&)>& g, const Draw& draw, int samples, unsigned seed) const {
    glm::dvec3 sum(0.0);
    visit_exact_integral(g, draw, samples, seed, [&](double factor, const glm::dvec3& l) { sum += factor * exact_spectral_weights(l); });
    return sum;
}

std::vector<double> EnvironmentLookup::exact_spectral_integral_spectrum(const std::function<double(const glm::dvec3&)>& g, const Draw& draw, int samples,
                                                                         unsigned seed) const {
    constexpr int first = lighting::SpectralForm::kFirstNm, last = lighting::SpectralForm::kLastNm;
    std::vector<double> sum(last - first + 1, 0.0);
    visit_exact_integral(g, draw, samples, seed, [&](double factor, const glm::dvec3& l) {
        if (factor == 0.0) return;
        const glm::dvec3 w = exact_spectral_weights(l);
        for (int nm = first; nm <= last; ++nm) sum[static_cast<size_t>(nm - first)] += factor * exact_spectral_radiance(w, nm);
    });
    return sum;
}

glm::dvec3 EnvironmentLookup::unfiltered(const glm::dvec3& world) const {
    return glm::dvec3(lighting::sample_bilinear(maps_->unfiltered().radiance, rotation_ * world)) * intensity_;
}

glm::dvec3 EnvironmentLookup::discs(const brdf::Directions& d, const std::function<glm::dvec3(const glm::dvec3&)>& f) const {
    glm::dvec3 sum(0.0);
    const glm::dmat3 to_world = glm::transpose(rotation_);  // rotations: the inverse is the transpose
    for (const lighting::DiscLight& disc : maps_->unfiltered().discs) {
        const std::vector<glm::dvec3> points = disc.quadrature(to_world * disc.direction);
        for (const glm::dvec3& l : points) {
            const double nl = glm::dot(d.n, l);
            if (nl > 0.0) sum += f(l) * nl * disc.radiance * intensity_ * disc.solid_angle() / static_cast<double>(points.size());
        }
    }
    return sum;
}

glm::dvec3 EnvironmentLookup::discs_shaded(const brdf::Directions& d, const std::function<glm::dvec3(const glm::dvec3&)>& f, double alpha) const {
    glm::dvec3 sum(0.0);
    const glm::dmat3 to_world = glm::transpose(rotation_);
    const glm::dvec3 r = 2.0 * glm::dot(d.n, d.v) * d.n - d.v;
    for (const lighting::DiscLight& disc : maps_->unfiltered().discs) {
        const double widened = lighting::disc_widened_alpha(alpha, disc.angular_radius), b = disc.angular_radius / 2;
        const glm::dvec3 l = lighting::DiscLight::nearest(to_world * disc.direction, r, disc.angular_radius * b * b / (widened * widened));
        const double nl = glm::dot(d.n, l);
        if (nl <= 0.0) continue;
        const glm::dvec3 value = f(l);
        if (!(std::isfinite(value.r) && std::isfinite(value.g) && std::isfinite(value.b))) continue;
        sum += value * nl * disc.radiance * disc.solid_angle() * intensity_ * (alpha * alpha) / (widened * widened);
    }
    return sum;
}

brdf::Directions environment_facing(const brdf::Directions& d) {
    const double nv = glm::dot(d.n, d.v);
    if (nv >= 0.01) return d;
    brdf::Directions bent = d;
    bent.n = glm::normalize(d.n + (0.01 - nv) * d.v);
    bent.t = glm::normalize(d.t - bent.n * glm::dot(bent.n, d.t));
    return bent;
}

glm::dvec3 metallic_roughness_compensated(const EnvironmentLookup& environment, const brdf::Directions& d, const brdf::MetallicRoughness& m,
                                          bool compensation) {
    if (glm::dot(d.n, d.l) <= 0.0 || glm::dot(d.n, d.v) <= 0.0) return glm::dvec3(0.0);
    const glm::dvec3 f = brdf::evaluate(m, d);
    if (!compensation) return f;
    const glm::dvec3 h = glm::normalize(d.l + d.v);
    const glm::dvec3 f0 = glm::mix(glm::dvec3(0.04), m.base_color, m.metallic);
    const glm::dvec3 fresnel = f0 + (1.0 - f0) * std::pow(1.0 - std::max(glm::dot(d.v, h), 0.0), 5.0);
    const glm::dvec3 diffuse = (1.0 - fresnel) * (1.0 - m.metallic) * m.base_color / std::numbers::pi;
    const glm::dvec3 ab = environment.dfg(glm::dot(d.n, d.v), m.roughness);
    return diffuse + (f - diffuse) * (1.0 + f0 * (1.0 / std::max(ab.x + ab.y, 1e-4) - 1.0));
}

glm::dvec3 metallic_roughness_environment(const EnvironmentLookup& environment, const brdf::Directions& facing, const brdf::MetallicRoughness& m,
                                          bool compensation, bool lobe_sampling, double* seam) {
    const brdf::Directions d = environment_facing(facing);
    const double nv = glm::dot(d.n, d.v);
    const glm::dvec3 f0 = glm::mix(glm::dvec3(0.04), m.base_color, m.metallic);
    const glm::dvec3 ab = environment.dfg(nv, m.roughness);
    const glm::dvec3 scale = compensation ? 1.0 + f0 * (1.0 / std::max(ab.x + ab.y, 1e-4) - 1.0) : glm::dvec3(1.0);
    // environment_pbr.glsl's environment_specular_radiance: the sampled lobe, blending into the
    // dominant direction's level from roughness 0.5 to 1 (or that level alone).
    const double t = lobe_sampling ? std::clamp(2.0 * m.roughness - 1.0, 0.0, 1.0) : 1.0;
    glm::dvec3 radiance(0.0);
    if (t < 1.0) radiance += (1.0 - t) * environment.lobe_radiance(d.n, d.v, f0, m.roughness, seam);
    if (t > 0.0) {
        const double a = std::clamp(m.roughness, 0.0, 1.0), s = (1.0 - a) * (std::sqrt(1.0 - a) + a);
        double seam_dominant = 0.0;
        radiance += t * environment.radiance(glm::normalize(glm::mix(d.n, 2.0 * nv * d.n - d.v, s)), m.roughness, seam ? &seam_dominant : nullptr);
        if (seam) *seam = std::max(*seam, seam_dominant);
    }
    const glm::dvec3 specular = (f0 * ab.x + ab.y) * scale * radiance;
    const glm::dvec3 map = specular + (1.0 - f0) * (1.0 - ab.z) * (1.0 - m.metallic) * m.base_color * environment.map_irradiance(d.n);
    // The disc lights through the BRDF at their centres, its lobe widened by each (metallic_roughness_discs).
    glm::dvec3 discs(0.0);
    const glm::dmat3 to_world = glm::transpose(environment.rotation_);
    const double alpha = m.roughness * m.roughness;
    for (const lighting::DiscLight& disc : environment.maps_->unfiltered().discs) {
        const glm::dvec3 l = to_world * disc.direction, h = glm::normalize(l + d.v);
        const double nl = glm::dot(d.n, l);
        if (nl <= 0.0) continue;
        const glm::dvec3 fresnel = f0 + (1.0 - f0) * std::pow(std::clamp(1.0 - glm::dot(d.v, h), 0.0, 1.0), 5.0);
        const glm::dvec3 diffuse = (1.0 - fresnel) * (1.0 - m.metallic) * m.base_color / std::numbers::pi;
        const glm::dvec3 specular = brdf::ggx_distribution(glm::dot(d.n, h), lighting::disc_widened_alpha(alpha, disc.angular_radius)) *
                                    brdf::smith_ggx_correlated(nl, nv, alpha) * fresnel / (4.0 * nl * nv);
        discs += (diffuse + specular * scale) * nl * disc.radiance * disc.solid_angle() * environment.intensity_;
    }
    return map + discs;
}

}  // namespace fxview::reference
