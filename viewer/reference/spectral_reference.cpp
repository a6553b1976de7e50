// Wavelength-based lighting from the physics (DOMAIN.md §2): the radiance reaching the eye at each
// sampled wavelength is light(l) * (object(l) * kd * cos(theta_i) + ks * specular), eq. 56 with
// Lambert and (modified-free) Phong/Blinn lobes; the tristimulus values are the CMF-weighted sum
// normalised by k = 1 / sum ybar (or the user's k); eq. 9 maps XYZ to linear sRGB.
// The spectra and CMFs are read from the same packed textures the GPU samples (so 8-bit storage
// is quantised alike); everything else is double precision.
#include "reference/spectral_reference.hpp"

#include <algorithm>
#include <cmath>
#include <functional>

#include "reference/spectral_integration.hpp"
#include "spectral/level_of_detail.hpp"

namespace fxview::reference {
namespace {

struct Lobes {
    double lambert = 0, phong = 0, blinn = 0;
};

// `rounding`: the relative float error of the lobe's base (a cosine, ~2 ulps) that pow() raises to
// the power; the slack evaluates the lobes with it.
Lobes lobes(const ShadingInput& in, double power, double rounding = 0.0) {
    const glm::dvec3 n = glm::normalize(in.normal);
    const glm::dvec3 l = glm::normalize(in.light - in.position);
    const glm::dvec3 v = glm::normalize(in.camera - in.position);
    Lobes lobes;
    lobes.lambert = std::max(glm::dot(n, l), 0.0);
    if (lobes.lambert > 0) {
        const glm::dvec3 mirror = 2.0 * glm::dot(n, l) * n - l;  // l reflected about n
        lobes.phong = std::pow(std::max(glm::dot(mirror, v), 0.0) * (1.0 + rounding), power);
        lobes.blinn = std::pow(std::max(glm::dot(n, glm::normalize(l + v)), 0.0) * (1.0 + rounding), power);
    }
    return lobes;
}

// Diffuse (kd * cos) and specular weights with the light and object spectra of the library.
// A highlight's slack: what turning the normal by a few ulps changes (its flanks), plus what the
// float rounding of the lobe's base, raised to the power, changes (its peak, where the first is 0).
using LobeShader = std::function<std::array<double, 4>(const ShadingInput&, const ReferenceContext&, double rounding)>;

std::function<double(const ShadingInput&, const ReferenceContext&)> highlight_slack(const LobeShader& shade) {
    return [shade](const ShadingInput& in, const ReferenceContext& c) {
        const Shader exact = [&shade](const ShadingInput& i, const ReferenceContext& context) { return shade(i, context, 0.0); };
        const std::array<double, 4> at = exact(in, c), rounded = shade(in, c, 2.4e-7);
        double change = 0;
        for (size_t i = 0; i < 3; ++i) change = std::max(change, std::abs(rounded[i] - at[i]));
        return change + normal_sensitivity(exact, in, c);
    };
}

Reference from_lobe_shader(const LobeShader& shade) {
    Reference r;
    r.shade = [shade](const ShadingInput& in, const ReferenceContext& c) { return shade(in, c, 0.0); };
    r.slack = highlight_slack(shade);
    return r;
}

Reference shaded(int specular_lobe /* 0 none, 1 Phong, 2 Blinn */, bool constant_spectra, bool every_nm) {
    Reference r = from_lobe_shader([=](const ShadingInput& in, const ReferenceContext& c, double rounding) {
        const SpectralSetup s = spectral_setup(c);
        const int light_index = static_cast<int>(c.number("LightSpectrum")), object_index = static_cast<int>(c.number("ObjectSpectrum"));
        const Lobes lobe = lobes(in, c.number("Power"), rounding);
        const double diffuse = c.number("Kd") * lobe.lambert;
        const double specular = specular_lobe == 0 ? 0.0 : c.number("Ks") * (specular_lobe == 1 ? lobe.phong : lobe.blinn);
        const auto xyz = integrate(s, every_nm, [&](int nm) {
            const double light = constant_spectra ? 1.0 : spectral::packed_value(*s.spectra, light_index, nm);
            const double object = constant_spectra ? 1.0 : spectral::packed_value(*s.spectra, object_index, nm);
            return light * (object * diffuse + specular);
        });
        return to_rgba(xyz, s.mapping);
    });
    if (specular_lobe == 0) r.slack = nullptr;
    r.tolerance = 5e-5;
    r.why = "float32 on the GPU against double here: a sum of up to 471 products (rounding about 1e-6 of the "
            "result in practice) and pow() of the specular lobe in float; measured on llvmpipe at most 9e-6, "
            "5e-5 leaves room for other drivers' pow/exp; in a highlight, the change that turning the normal by "
            "1e-6 rad, or the lobe's base by 2.4e-7 relative before pow(), causes is the pixel's slack";
    return r;
}

}  // namespace

std::map<std::string, Reference> spectral_references() {
    std::map<std::string, Reference> all;
    all.emplace("Constant", shaded(0, true, false));
    all.emplace("ConstantUnoptimised", shaded(0, true, false));
    all.emplace("Lambert", shaded(0, false, false));
    all.emplace("Single", shaded(0, false, false));
    all.emplace("Phong", shaded(1, false, false));
    all.emplace("Blinn", shaded(2, false, false));
    all.emplace("Combined", shaded(0, false, true));

    // Code 11's metal switch as the thesis' text has it: a metal's highlight has the object's colour,
    // a dielectric's the light's (the listing swaps the branches).
    Reference phong_metal = from_lobe_shader([](const ShadingInput& in, const ReferenceContext& c, double rounding) {
        const SpectralSetup s = spectral_setup(c);
        const int light_index = static_cast<int>(c.number("LightSpectrum")), object_index = static_cast<int>(c.number("ObjectSpectrum"));
        const Lobes lobe = lobes(in, c.number("Power"), rounding);
        const double diffuse = c.number("Kd") * lobe.lambert, specular = c.number("Ks") * lobe.phong;
        const auto light = [&](int nm) { return spectral::packed_value(*s.spectra, light_index, nm); };
        const auto object = [&](int nm) { return spectral::packed_value(*s.spectra, object_index, nm); };
        if (c.number("Metal") == 0.0) {
            const auto body = to_rgba(integrate(s, true, [&](int nm) { return light(nm) * object(nm) * diffuse; }), s.mapping);
            const auto highlight = to_rgba(integrate(s, true, [&](int nm) { return light(nm) * specular; }), s.mapping);
            return std::array<double, 4>{body[0] + highlight[0], body[1] + highlight[1], body[2] + highlight[2], 1.0};
        }
        return to_rgba(integrate(s, true, [&](int nm) { return light(nm) * object(nm) * (diffuse + specular); }), s.mapping);
    });
    phong_metal.tolerance = 5e-5;
    phong_metal.why = all.at("Phong").why;
    all.emplace("CombinedPhong", std::move(phong_metal));

    // Level of detail (ch. 4.6): CMFs and spectra linearly interpolated between support points
    // every 2^(9 - level) nm; every nm of the range enters the sum.
    Reference lod = from_lobe_shader([](const ShadingInput& in, const ReferenceContext& c, double rounding) {
        const SpectralSetup s = spectral_setup(c);
        const int light_index = static_cast<int>(c.number("LightSpectrum")), object_index = static_cast<int>(c.number("ObjectSpectrum"));
        const int spacing = spectral::lod_spacing(std::clamp(static_cast<int>(c.number("LodLevel")), 1, spectral::kLodLevels));
        const Lobes lobe = lobes(in, c.number("Power"), rounding);
        const double diffuse = c.number("Kd") * lobe.lambert, specular = c.number("Ks") * lobe.phong;
        const auto at_support = [&](const std::function<double(int)>& f, int nm) {
            return spectral::lod_interpolated(f, nm, s.lower, s.upper, spacing);
        };
        spectral::Vec3 xyz{0, 0, 0};
        double ybar = 0;
        for (int nm = s.lower; nm <= s.upper; ++nm) {
            const double light = at_support([&](int at) { return spectral::packed_value(*s.spectra, light_index, at); }, nm);
            const double object = at_support([&](int at) { return spectral::packed_value(*s.spectra, object_index, at); }, nm);
            for (int i = 0; i < 3; ++i) {
                const double cmf = at_support([&](int at) { return spectral::cmf_value(*s.cmf, s.observer, at)[i] * s.cmf_unit; }, nm);
                xyz[i] += light * (object * diffuse + specular) * cmf;
                if (i == 1) ybar += cmf;
            }
        }
        const double k = (s.k > 0 ? s.k : 1.0 / ybar) * s.brightness;
        for (double& v : xyz) v *= k;
        return to_rgba(xyz, s.mapping);
    });
    lod.tolerance = 5e-5;
    lod.why = all.at("Phong").why;
    all.emplace("LodPhong", std::move(lod));
    return all;
}

}  // namespace fxview::reference
