// Wavelength-based lighting from the physics (DOMAIN.md §2): the radiance reaching the eye at each
// sampled wavelength is light(l) * (object(l) * kd * cos(theta_i) + ks * specular), eq. 56 with
// Lambert and (modified-free) Phong/Blinn lobes; the tristimulus values are the CMF-weighted sum
// normalised by k = 1 / sum ybar (or the user's k); eq. 9 maps XYZ to linear sRGB.
// The spectra and CMFs are read from the same packed textures the GPU samples (so 8-bit storage
// is quantised alike); everything else is double precision. Under an environment with a spectral
// form the surroundings add their light, read as environment_spectral_lobes.glsl reads it; the ground
// truth integrates the environment's model over the sphere instead, every nm.
#include "reference/spectral_reference.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <optional>

#include "reference/environment_reference.hpp"
#include "reference/spectral_integration.hpp"
#include "reference/flat_lamp.hpp"
#include "reference/sphere_lamp.hpp"
#include "reference/tangent_frame.hpp"
#include "spectral/level_of_detail.hpp"

namespace fxview::reference {
namespace {

constexpr double kPi = std::numbers::pi;
// GL filters with limited sub-texel precision (llvmpipe: 8 bits): a bilinear weight may be off by
// 1/512 of the difference of neighbouring texels. Measured under the sky, studio and furnace: see make().
constexpr double kEnvironmentTolerance = 1e-3;

// The environment's light on the surface as weights of its three spectra: the diffuse part (times Kd,
// to be multiplied by the object's spectrum) and the highlight (times Ks). Absent without a spectral form.
struct Surroundings {
    EnvironmentLookup environment;
    glm::dvec3 diffuse{0.0}, highlight{0.0};
    double seam = 0.0;  // how far GL's filtering leaves the weights open (cube corners, sub-texel precision)
    bool exact = false;  // the ground truth's: the model's spectra in double
    // The ground truth under an image: the integrals as spectra (360-830 nm), each direction's own uplift.
    std::vector<double> diffuse_spectrum{}, highlight_spectrum{};
    double at(const glm::dvec3& weights, int nm) const {
        return exact ? environment.exact_spectral_radiance(weights, nm) : environment.spectral_radiance(weights, nm);
    }
    double diffuse_at(int nm) const { return diffuse_spectrum.empty() ? at(diffuse, nm) : diffuse_spectrum[static_cast<size_t>(nm - 360)]; }
    double highlight_at(int nm) const { return highlight_spectrum.empty() ? at(highlight, nm) : highlight_spectrum[static_cast<size_t>(nm - 360)]; }
};

// A unit direction about `axis` at polar cosine `cosine` and azimuth 2π u (Duff et al.'s frame, as the GPU).
glm::dvec3 about(const glm::dvec3& axis, double cosine, double u) {
    glm::dvec3 x, y;
    duff_frame(axis, x, y);
    const double sine = std::sqrt(std::max(0.0, 1.0 - cosine * cosine));
    return sine * std::cos(2.0 * kPi * u) * x + sine * std::sin(2.0 * kPi * u) * y + cosine * axis;
}

// lobe: 0 none, 1 Phong, 2 Blinn. `truth_seed`: the ground truth (the model's weights, 2048 directions
// per lobe drawn as the lobe, the sun by quadrature) instead of the GPU's tables.
std::optional<Surroundings> surroundings(const ShadingInput& in, const ReferenceContext& c, int lobe, const unsigned* truth_seed = nullptr) {
    std::optional<EnvironmentLookup> environment = EnvironmentLookup::from(c);
    if (!environment || !environment->spectral()) return std::nullopt;
    Surroundings s{.environment = *environment};
    const glm::dvec3 n = glm::normalize(in.normal), v = glm::normalize(in.camera - in.position), r = 2.0 * glm::dot(n, v) * n - v;
    const double power = c.number("Power");
    if (!truth_seed) {
        double seam_diffuse = 0.0, seam_highlight = 0.0;
        s.diffuse = c.number("Kd") * environment->spectral_irradiance(n, &seam_diffuse);
        if (lobe != 0) s.highlight = c.number("Ks") * environment->spectral_highlight(n, v, lobe == 2, power, &seam_highlight);
        s.seam = c.number("Kd") * seam_diffuse + c.number("Ks") * seam_highlight;
        return s;
    }
    constexpr int kSamples = 2048;
    s.exact = true;
    // Into weights (three spectra) or, under an image, into a spectrum: the integral of each direction's own one.
    const auto gather = [&](double scale, const std::function<double(const glm::dvec3&)>& g, const EnvironmentLookup::Draw& draw, unsigned seed,
                            glm::dvec3& weights, std::vector<double>& spectrum) {
        if (!environment->uplifted()) {
            weights = scale * environment->exact_spectral_integral(g, draw, kSamples, seed);
            return;
        }
        spectrum = environment->exact_spectral_integral_spectrum(g, draw, kSamples, seed);
        for (double& v : spectrum) v *= scale;
    };
    gather(
        c.number("Kd"), [&](const glm::dvec3& l) { return std::max(glm::dot(n, l), 0.0); },
        [&](const glm::dvec2& u, double& density) {
            const double cosine = std::sqrt(1.0 - u.x);
            density = cosine / kPi;
            return about(n, cosine, u.y);
        },
        *truth_seed, s.diffuse, s.diffuse_spectrum);
    if (lobe == 1)
        gather(
            c.number("Ks"),
            [&](const glm::dvec3& l) { return glm::dot(n, l) > 0.0 ? std::pow(std::max(glm::dot(r, l), 0.0), power) : 0.0; },
            [&](const glm::dvec2& u, double& density) {
                const double cosine = std::pow(1.0 - u.x, 1.0 / (power + 1.0));
                density = (power + 1.0) / (2.0 * kPi) * std::pow(cosine, power);
                return about(r, cosine, u.y);
            },
            *truth_seed + 1u, s.highlight, s.highlight_spectrum);
    if (lobe == 2)
        gather(
            c.number("Ks"),
            [&](const glm::dvec3& l) { return glm::dot(n, l) > 0.0 ? std::pow(std::max(glm::dot(n, glm::normalize(l + v)), 0.0), power) : 0.0; },
            [&](const glm::dvec2& u, double& density) {
                const double cosine = std::pow(1.0 - u.x, 1.0 / (power + 1.0));
                const glm::dvec3 h = about(n, cosine, u.y);
                const double vh = glm::dot(v, h);
                density = vh > 0.0 ? (power + 1.0) / (2.0 * kPi) * std::pow(cosine, power) / (4.0 * vh) : 0.0;
                return 2.0 * vh * h - v;
            },
            *truth_seed + 2u, s.highlight, s.highlight_spectrum);
    return s;
}

// How far the linear output may move from the surroundings' seams.
double seam_slack(const SpectralSetup& s, const Surroundings& env) {
    SpectralSetup unlit = s;
    unlit.brightness = 1.0;
    return colour_uncertainty(unlit, [&](int nm) {
        return env.seam * (std::abs(env.at({1, 0, 0}, nm)) + std::abs(env.at({0, 1, 0}, nm)) + std::abs(env.at({0, 0, 1}, nm)));
    });
}

// The lamp's factors cos θ and lobes: at its centre for a point; for a sphere lamp (`--light-radius`)
// as the GPU averages them over its disc, for a flat one (`--light-shape disc|rectangle`) as the GPU
// sums them over its points; or (`truth`) integrated over the light by an independent rule.
// `rounding`: the relative float error of the lobe's base (a cosine, ~2 ulps) that pow() raises to
// the power; the slack evaluates the lobes with it.
LampFactors lobes(const ShadingInput& in, double power, bool with_lobes, double rounding = 0.0, bool truth = false) {
    const glm::dvec3 n = glm::normalize(in.normal);
    const glm::dvec3 l = glm::normalize(in.light - in.position);
    const glm::dvec3 v = glm::normalize(in.camera - in.position);
    if (in.lamp.is_flat())
        return truth ? flat_lamp_integral(in.lamp, in.position, n, v, power) : flat_lamp_factors(in.lamp, in.position, n, v, power, with_lobes, rounding);
    if (in.light_radius > 0.0) {
        const double sin_alpha = std::min(in.light_radius / glm::length(in.light - in.position), 0.999);
        return truth ? sphere_lamp_integral(n, v, l, sin_alpha, power) : sphere_lamp_factors(n, v, l, sin_alpha, power, with_lobes, rounding);
    }
    LampFactors lobes;
    lobes.lambert = std::max(glm::dot(n, l), 0.0);
    if (lobes.lambert > 0) {
        const glm::dvec3 mirror = 2.0 * glm::dot(n, l) * n - l;  // l reflected about n
        lobes.phong = std::pow(std::max(glm::dot(mirror, v), 0.0) * (1.0 + rounding), power);
        lobes.blinn = std::pow(std::max(glm::dot(n, glm::normalize(l + v)), 0.0) * (1.0 + rounding), power);
    }
    return lobes;
}

// The lamp's part: kd cos θ and the highlight lobe times ks, and the library spectra of light and
// object (-1: a constant 1, the Constant techniques).
struct Lamp {
    double diffuse = 0, specular = 0;
    int light = -1, object = -1;
};

Lamp lamp(const ShadingInput& in, const ReferenceContext& c, int lobe /* 0 none, 1 Phong, 2 Blinn */, double rounding, bool constant_spectra,
          bool truth = false) {
    const LampFactors l = lobes(in, c.number("Power"), lobe != 0, rounding, truth);
    Lamp lamp;
    lamp.diffuse = c.number("Kd") * l.lambert;
    lamp.specular = lobe == 0 ? 0.0 : c.number("Ks") * (lobe == 1 ? l.phong : l.blinn);
    if (!constant_spectra) {
        lamp.light = static_cast<int>(c.number("LightSpectrum"));
        lamp.object = static_cast<int>(c.number("ObjectSpectrum"));
    }
    return lamp;
}

double spectrum(const SpectralSetup& s, int index, int nm) { return index < 0 ? 1.0 : spectral::packed_value(*s.spectra, index, nm); }

// Which light a sum takes: all of it, the object-coloured body, or the highlight (Code 11 converts
// the last two to RGB apart).
enum class Part { Whole, Body, Highlight };

// Brightness · light (object · diffuse + specular) + the surroundings' object · E + H, summed against
// the CMFs; `metal`: the highlights object-coloured too.
spectral::Vec3 lit(const SpectralSetup& s, bool every_nm, const Lamp& lamp, const std::optional<Surroundings>& env, Part part, bool metal = false) {
    SpectralSetup unlit = s;
    unlit.brightness = 1.0;
    return integrate(unlit, every_nm, [&](int nm) {
        const double light = spectrum(s, lamp.light, nm) * s.brightness, object = spectrum(s, lamp.object, nm);
        const double diffuse = env ? env->diffuse_at(nm) : 0.0, highlight = env ? env->highlight_at(nm) : 0.0;
        const double body = object * (light * lamp.diffuse + diffuse), shine = (metal ? object : 1.0) * (light * lamp.specular + highlight);
        return part == Part::Body ? body : part == Part::Highlight ? shine : body + shine;
    });
}

// A technique's colour from its lamp and surroundings (whether the sums take every nm, which lobe,
// Code 11's composition: `split` adds body and highlight in RGB unless `metal`).
struct Technique {
    int lobe = 0;
    bool constant_spectra = false, every_nm = false, split = false;
};

std::array<double, 4> colour(const SpectralSetup& s, bool every_nm, const Lamp& l, const std::optional<Surroundings>& env, const Technique& t,
                             const ReferenceContext& c) {
    if (!t.split || c.number("Metal") != 0.0) return to_rgba(lit(s, every_nm, l, env, Part::Whole, t.split), s.mapping);
    const auto body = to_rgba(lit(s, every_nm, l, env, Part::Body), s.mapping), highlight = to_rgba(lit(s, every_nm, l, env, Part::Highlight), s.mapping);
    return {body[0] + highlight[0], body[1] + highlight[1], body[2] + highlight[2], 1.0};
}

// The reference from `shade` (the technique's sums; `rounding` as lobes() takes it): its slack the
// highlight's sensitivity plus the surroundings' seams; its ground truth the technique's model with
// every nm and the surroundings integrated over the environment's model.
using LobeShader = std::function<std::array<double, 4>(const ShadingInput&, const ReferenceContext&, double rounding)>;

Reference make(const LobeShader& shade, const Technique& t) {
    Reference r;
    r.shade = [shade](const ShadingInput& in, const ReferenceContext& c) { return shade(in, c, 0.0); };
    r.slack = [shade, t](const ShadingInput& in, const ReferenceContext& c) {
        double change = 0;
        if (t.lobe != 0) {
            // A highlight's slack: what turning the normal by a few ulps changes (its flanks), plus what
            // the float rounding of the lobe's base, raised to the power, changes (its peak).
            const Shader exact = [&shade](const ShadingInput& i, const ReferenceContext& context) { return shade(i, context, 0.0); };
            // A sized lamp's count of points may step either way: both signs there.
            const std::array<double, 4> at = exact(in, c), up = shade(in, c, 2.4e-7), down = in.light_radius > 0.0 || in.lamp.is_flat() ? shade(in, c, -2.4e-7) : at;
            for (size_t i = 0; i < 3; ++i) change = std::max({change, std::abs(up[i] - at[i]), std::abs(down[i] - at[i])});
            change += normal_sensitivity(exact, in, c);
        }
        const std::optional<Surroundings> env = t.constant_spectra ? std::nullopt : surroundings(in, c, t.lobe);
        return change + (env ? seam_slack(spectral_setup(c), *env) : 0.0);
    };
    if (!t.constant_spectra)
        r.truth = [t](const ShadingInput& in, const ReferenceContext& c, unsigned seed) {
            return colour(every_nm_setup(c), true, lamp(in, c, t.lobe, 0.0, false, true), surroundings(in, c, t.lobe, &seed), t, c);
        };
    r.truth_method = "the lamp and the environment at every nm: a sphere lamp over its disc (128 x 256 points), a flat lamp over its surface (96 x 192 or 160 x 160 elements), an environment's model over the sphere (an image: each direction's own uplifted spectrum; 2048 directions per lobe, the sun by quadrature)";
    r.truth_with_sized_light = true;
    r.tolerance = 5e-5;
    r.why = "float32 on the GPU against double here: a sum of up to 471 products (rounding about 1e-6 of the "
            "result in practice) and pow() of the specular lobe in float; measured on llvmpipe at most 9e-6, "
            "5e-5 leaves room for other drivers' pow/exp; in a highlight, the change that turning the normal by "
            "1e-6 rad, or the lobe's base by 2.4e-7 relative before pow(), causes is the pixel's slack; under an "
            "environment, the spread of the weight texels at cube corners too";
    r.tolerance_for = [](const ReferenceContext& c) {
        // Under an environment: GL filters with limited sub-texel precision (llvmpipe 8 bits): a bilinear
        // weight may be off by 1/512, of the difference of neighbouring weight texels.
        return 5e-5 * output_gain(spectral_setup(c), 2.0) + (c.environment && !c.environment->source.empty() ? kEnvironmentTolerance : 0.0);
    };
    return r;
}

Reference shaded(const Technique& t) {
    return make([t](const ShadingInput& in, const ReferenceContext& c, double rounding) {
        const std::optional<Surroundings> env = t.constant_spectra ? std::nullopt : surroundings(in, c, t.lobe);
        return colour(spectral_setup(c), t.every_nm, lamp(in, c, t.lobe, rounding, t.constant_spectra), env, t, c);
    }, t);
}

}  // namespace

std::map<std::string, Reference> spectral_references() {
    std::map<std::string, Reference> all;
    all.emplace("Constant", shaded({0, true, false}));
    all.emplace("ConstantUnoptimised", shaded({0, true, false}));
    all.emplace("Lambert", shaded({0, false, false}));
    all.emplace("Single", shaded({0, false, false}));
    all.emplace("Phong", shaded({1, false, false}));
    all.emplace("Blinn", shaded({2, false, false}));
    all.emplace("Combined", shaded({0, false, true}));
    // Code 11's metal switch as the thesis' text has it: a metal's highlight has the object's colour,
    // a dielectric's the light's (the listing swaps the branches).
    all.emplace("CombinedPhong", shaded({1, false, true, true}));

    // Level of detail (ch. 4.6): CMFs, spectra and the surroundings' spectra linearly interpolated
    // between support points every 2^(9 - level) nm; every nm of the range enters the sum.
    all.emplace("LodPhong", make([](const ShadingInput& in, const ReferenceContext& c, double rounding) {
        const SpectralSetup s = spectral_setup(c);
        const int spacing = spectral::lod_spacing(std::clamp(static_cast<int>(c.number("LodLevel")), 1, spectral::kLodLevels));
        const Lamp l = lamp(in, c, 1, rounding, false);
        const std::optional<Surroundings> env = surroundings(in, c, 1);
        const auto at_support = [&](const std::function<double(int)>& f, int nm) { return spectral::lod_interpolated(f, nm, s.lower, s.upper, spacing); };
        spectral::Vec3 xyz{0, 0, 0};
        double ybar = 0;
        for (int nm = s.lower; nm <= s.upper; ++nm) {
            const double light = at_support([&](int at) { return spectrum(s, l.light, at); }, nm);
            const double object = at_support([&](int at) { return spectrum(s, l.object, at); }, nm);
            const double diffuse = env ? at_support([&](int at) { return env->at(env->diffuse, at); }, nm) : 0.0;
            const double highlight = env ? at_support([&](int at) { return env->at(env->highlight, at); }, nm) : 0.0;
            const double weight = light * (object * l.diffuse + l.specular) * s.brightness + object * diffuse + highlight;
            for (int i = 0; i < 3; ++i) {
                const double cmf = at_support([&](int at) { return spectral::cmf_value(*s.cmf, s.observer, at)[i] * s.cmf_unit; }, nm);
                xyz[i] += weight * cmf;
                if (i == 1) ybar += cmf;
            }
        }
        const double k = s.k > 0 ? s.k : 1.0 / ybar;
        for (double& v : xyz) v *= k;
        return to_rgba(xyz, s.mapping);
    }, {1, false, false}));
    return all;
}

}  // namespace fxview::reference
