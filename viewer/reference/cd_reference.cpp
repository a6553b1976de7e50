// CD diffraction from viewer/optics/grating (double precision): the thesis' eq. 72, and the square
// patch of N tracks averaged over the pixel's footprint by quadrature of explicit phasor sums (the
// GLSL uses a Fourier series and the sine integral). Both are steep or discontinuous in
// x = d u / λ, whose float value on the GPU is a few ulps off; the slack is what that uncertainty
// can change at each pixel.
#include "reference/cd_reference.hpp"

#include <algorithm>
#include <cmath>

#include "optics/grating.hpp"
#include "optics/grating_orders.hpp"
#include "reference/flat_lamp.hpp"
#include "reference/environment_reference.hpp"
#include "reference/spectral_integration.hpp"

namespace fxview::reference {
namespace {

struct Disc {
    glm::dvec3 n, l, v, across, along;
};

Disc disc(const ShadingInput& in) {
    Disc d;
    d.n = glm::normalize(in.normal);
    d.l = glm::normalize(in.light - in.position);
    d.v = glm::normalize(in.camera - in.position);
    const glm::dvec3 t = glm::normalize(in.tangent - d.n * glm::dot(d.n, in.tangent));
    const glm::dvec3 b = glm::cross(d.n, t);
    const glm::dvec2 radial = in.uv - 0.5;
    d.across = glm::dot(radial, radial) > 0 ? glm::normalize(radial.x * t + radial.y * b) : t;
    d.along = glm::cross(d.n, d.across);
    return d;
}

// Diffracted intensity at one wavelength, and how far it can move when x is off by its float error.
// The value is computed only where it is wanted (the grating's quadrature is costly).
struct Sample {
    double intensity, uncertainty;
};
using Diffraction = std::function<Sample(const Disc&, const ShadingInput&, const ReferenceContext&, int nm, bool want_intensity)>;

// The float error of x = d·u/λ on the GPU: a handful of roundings in normalisations, dot products
// and the division (each ~6e-8 relative; 1e-6 is generous), plus the error of u itself, which is
// absolute where u is a difference of cosines (eq. 72) or a sum of components that cancel: a few
// ulps of each cosine, 4e-7.
double x_error(double x, double spacing_nm, int nm) { return 1e-6 * std::abs(x) + 4e-7 * spacing_nm / nm; }

Sample thesis_sample(const Disc& d, const ShadingInput&, const ReferenceContext& c, int nm, bool) {
    const double threshold = c.number("Threshold");
    const auto r = optics::thesis::cd_intensity(c.number("TrackSpacing"), std::abs(glm::dot(d.along, d.l)), glm::dot(d.n, d.v),
                                                glm::dot(d.n, d.l), nm, threshold);
    const double fraction = r.cycles - std::floor(r.cycles), error = x_error(r.cycles, r.spacing_nm, nm);
    // frac() jumps at integers (from ~1 to 0) and the cut at the threshold (from ~threshold to 0).
    const bool near_integer = r.cycles >= 0.5 && std::abs(r.cycles - std::round(r.cycles)) < error;
    const bool near_threshold = std::abs(fraction - threshold) < error;
    return {r.intensity, near_integer ? 1.0 : near_threshold ? threshold + error : error};
}

// The square patch of N tracks, averaged over the pixel's footprint as the GPU captured it: by
// quadrature of the explicit phasor sum (optics/grating.hpp), not by the shader's series. Its slack
// is the change the float error of x and y can cause, from the closed forms.
Sample grating_sample(const Disc& d, const ShadingInput& in, const ReferenceContext& c, int nm, bool want_intensity) {
    const int tracks = std::max(1, static_cast<int>(c.number("Tracks")));
    if (glm::dot(d.n, d.l) <= 0 || glm::dot(d.n, d.v) <= 0) return {0.0, 0.0};
    const double spacing = c.number("TrackSpacing");
    const double x = spacing * glm::dot(d.l + d.v, d.across) / nm, y = spacing * glm::dot(d.l + d.v, d.along) / nm;
    const double wx = in.footprint.x / nm, wy = in.footprint.y / nm;
    Sample s{0.0, 0.0};
    if (want_intensity)
        s.intensity = optics::tracks_box_average_quadrature(x, wx, tracks) * optics::patch_box_average_quadrature(y, wy, tracks);
    const double dx = x_error(x, spacing, nm), dy = x_error(y, spacing, nm);
    const double at = optics::tracks_box_average(x, wx, tracks) * optics::patch_box_average(y, wy, tracks);
    for (const double ex : {-dx, dx})
        for (const double ey : {-dy, dy})
            s.uncertainty = std::max(s.uncertainty, std::abs(optics::tracks_box_average(x + ex, wx, tracks) *
                                                                 optics::patch_box_average(y + ey, wy, tracks) -
                                                             at));
    return s;
}

// The energy-true orders (optics/grating_orders.hpp) in double: every propagating order's efficiency
// times the sphere light's radiance from the direction the grating equation picks (the GPU visits
// only the orders near the light). The shader draws no order past 32 (d <= 5000 nm has at most 28 at
// 360 nm); so neither does this. `offset` moves the view's component across the tracks and the
// chords to the light's centre by float-sized amounts, for the slack.
constexpr int kMaxOrder = 32;

// The model's settings from the effect's parameters.
optics::GratingOrderModel order_model(const ReferenceContext& c) {
    optics::GratingOrderModel model;
    model.spacing_nm = std::max(c.number("TrackSpacing"), 1.0);
    model.zero_order = c.number("ZeroOrder");
    model.pit_fraction = c.number("PitFraction");
    model.reflectance = c.number("Reflectance");
    return model;
}

// The propagating orders (at most ±kMaxOrder, as the shader) and their efficiencies, index m − first.
std::pair<optics::OrderRange, std::vector<double>> propagating(const glm::dvec3& view, double wavelength_nm, const optics::GratingOrderModel& model) {
    optics::OrderRange range = optics::propagating_orders(view, wavelength_nm, model.spacing_nm);
    range.first = std::max(range.first, -kMaxOrder);
    range.last = std::min(range.last, kMaxOrder);
    return {range, optics::order_efficiencies(model, range)};
}

// The scene environment the orders diffract: one with a spectral form (the sky, the studio), else none.
std::optional<EnvironmentLookup> surroundings_of(const ReferenceContext& c) {
    std::optional<EnvironmentLookup> environment = EnvironmentLookup::from(c);
    if (!environment || !environment->spectral() || !(c.environment->intensity > 0)) return std::nullopt;
    return environment;
}

// What the shader's lamp loop shares per pixel (cd.fx lamp_orders): the view and the light in the
// grating's frame, the chord `edge` that bounds the light's reach, its smallest angular half size,
// the most orders any sample has, and the orders' blur.
struct LampView {
    glm::dvec3 view{0.0};
    double centre = 0, edge = 0, size = 0, tracks = 1, spacing = 1600;
    int most = 0, step = 1, per_band = 1, last_sample = 0, lower = 360;
    double longest = 0, widest = 0;
};

LampView lamp_view(const Disc& d, const ShadingInput& in, const ReferenceContext& c, double offset) {
    LampView w;
    w.view = {glm::dot(d.v, d.across) + offset, glm::dot(d.v, d.along), glm::dot(d.v, d.n)};
    w.centre = w.view.x + glm::dot(d.l, d.across);
    const double distance = glm::length(in.light - in.position);
    const bool flat = in.lamp.is_flat();
    const double reach = flat ? (in.lamp.shape == scene::LightShape::Disc ? in.lamp.half_size.x : glm::length(in.lamp.half_size)) : std::max(in.light_radius, 0.0);
    w.edge = flat && reach >= distance ? 2.0 : optics::light_edge_chord(reach / distance);
    if (flat) {
        const glm::dvec2 h = scene::flat_light_angular_half_size(in.lamp, in.position);
        w.size = std::min(h.x, h.y);
    } else {
        w.size = w.edge;
    }
    w.tracks = std::max(1.0, c.number("Tracks"));
    w.spacing = std::max(c.number("TrackSpacing"), 1.0);
    w.lower = static_cast<int>(c.number("Lower"));
    const int upper = static_cast<int>(c.number("Upper"));
    w.step = std::max(static_cast<int>(c.number("Steps")), 1);
    w.last_sample = std::max(upper - w.lower, 0) / w.step;
    w.per_band = std::max(static_cast<int>(c.number("LampBand")) / w.step, 1);
    const double reach_v = std::sqrt(std::max(1.0 - w.view.y * w.view.y, 0.0));
    w.most = std::min(static_cast<int>(std::ceil((std::abs(w.view.x) + reach_v) * w.spacing / std::max(w.lower, 1))), kMaxOrder);
    w.longest = upper / w.spacing;
    w.widest = w.longest / w.tracks + in.footprint.x + w.most * w.longest * in.footprint.y;
    return w;
}

// Whether the shader follows the light's edge through bands (a light much larger than the orders'
// blur and than a band's step), and how near the decision is (relative).
std::pair<bool, double> lamp_banded(const LampView& w) {
    const double threshold = 2.0 * std::max(w.widest, w.most * w.per_band * w.step / w.spacing);
    return {w.per_band > 1 && w.size > threshold, std::abs(w.size - threshold) / std::max(threshold, 1e-30)};
}

// One order at one wavelength as the shader records it: its ramp u = 0.5 + angle / width (the angle
// from the light's outline, inside positive, −4 where the order misses), its radiance inside
// (efficiency included); `valid` false where the order does not propagate.
struct OrderRecord {
    double ramp = 0, rise = 0, scale = 0;  // rise: the height of the order's direction above the disc
    bool valid = false;
};

constexpr double kLowOrder = 0.25;  // cd.fx: below it an order's band is checked at its middle

OrderRecord order_record(const Disc& d, const ShadingInput& in, const optics::GratingOrderModel& model, const LampView& w, int m, double nm, double offset) {
    OrderRecord r;
    const double ratio = nm / model.spacing_nm, width = ratio / w.tracks + in.footprint.x + std::abs(m) * ratio * in.footprint.y;
    r.ramp = 0.5 - 4.0 / width;
    const auto l = optics::order_incidence(w.view, m, nm, model.spacing_nm);
    if (!l) return r;
    const auto [range, efficiencies] = propagating(w.view, nm, model);
    if (m < range.first || m > range.last) return r;
    const double efficiency = efficiencies[static_cast<size_t>(m - range.first)];
    const glm::dvec3 incidence = l->x * d.across + l->y * d.along + l->z * d.n;
    r.valid = true;
    r.rise = l->z;
    double angle = 0;
    if (in.lamp.is_flat()) {
        const auto hit = scene::flat_light_hit(in.lamp, in.position, glm::normalize(incidence));
        angle = hit ? std::max(hit->inside_angle, -4.0) : -4.0;
        r.scale = efficiency * scene::flat_light_ramp_scale(in.lamp, scene::flat_light_angular_half_size(in.lamp, in.position), width);
    } else {
        angle = std::max(w.edge - (glm::length(incidence - d.l) + offset), -4.0);
        r.scale = efficiency * optics::sphere_light_ramp_scale(w.edge, width);
    }
    r.ramp = 0.5 + angle / width;
    return r;
}

// Every order at exactly this wavelength.
double orders_radiance_exact(const Disc& d, const ShadingInput& in, const optics::GratingOrderModel& model, const LampView& w, int nm, double offset) {
    if (w.view.z <= 0) return 0.0;
    const auto [range, efficiencies] = propagating(w.view, nm, model);
    const double edge = optics::light_edge_chord(std::max(in.light_radius, 0.0) / glm::length(in.light - in.position));
    const double ratio = nm / model.spacing_nm;
    double radiance = 0;
    for (int m = range.first; m <= range.last; ++m) {
        const auto l = optics::order_incidence(w.view, m, nm, model.spacing_nm);
        if (!l) continue;
        const double efficiency = efficiencies[static_cast<size_t>(m - range.first)];
        const glm::dvec3 incidence = l->x * d.across + l->y * d.along + l->z * d.n;
        const double width = ratio / w.tracks + in.footprint.x + std::abs(m) * ratio * in.footprint.y;
        radiance += efficiency * (in.lamp.is_flat() ? scene::flat_light_radiance(in.lamp, in.position, glm::normalize(incidence), width)
                                                    : optics::sphere_light_radiance(glm::length(incidence - d.l) + offset, edge, width));
    }
    return radiance;
}

// The band of samples that holds nm: each order near the light at its two ends (as the shader picks
// them), its ramp and radiance inside interpolated linearly between the two records; an order near the
// horizon whose record at the band's middle is off that line by more than 0.02 (in the ramp, or
// relative in the radiance inside) is followed through both halves of the band.
double orders_radiance_banded(const Disc& d, const ShadingInput& in, const optics::GratingOrderModel& model, const LampView& w, int nm, double offset) {
    if (w.view.z <= 0) return 0.0;
    const int k = (nm - w.lower) / w.step, last_band = w.last_sample % w.per_band == 0 ? w.last_sample - w.per_band : w.last_sample / w.per_band * w.per_band;
    // The bands start at multiples of per_band; the last sample closes the band before it where it is one.
    const int k0 = std::min(k / w.per_band * w.per_band, std::max(last_band, 0)), k1 = std::min(k0 + w.per_band, w.last_sample);
    const double na = w.lower + k0 * w.step, nb = w.lower + k1 * w.step, ra = na / model.spacing_nm, rb = nb / model.spacing_nm;
    const double near = w.edge + 0.5 * (rb / w.tracks + in.footprint.x + w.most * rb * in.footprint.y);
    const double low = w.centre - near, high = w.centre + near;
    const int from = std::max(static_cast<int>(std::ceil(std::min(low / ra, low / rb))), -kMaxOrder);
    const int to = std::min(static_cast<int>(std::floor(std::max(high / ra, high / rb))), kMaxOrder);
    const double t = static_cast<double>(k - k0) / std::max(k1 - k0, 1);
    double radiance = 0;
    for (int m = from; m <= to; ++m) {
        OrderRecord a = order_record(d, in, model, w, m, na, offset), b = order_record(d, in, model, w, m, nb, offset);
        if (!a.valid && !b.valid) continue;  // evanescent at both ends
        bool linear = true;
        OrderRecord middle;
        if (std::min(a.rise, b.rise) < kLowOrder) {
            middle = order_record(d, in, model, w, m, 0.5 * (na + nb), offset);
            linear = a.valid == b.valid && middle.valid == a.valid &&
                     std::abs(std::clamp(middle.ramp, 0.0, 1.0) - std::clamp(0.5 * (a.ramp + b.ramp), 0.0, 1.0)) <= 0.02 &&
                     std::abs(middle.scale - 0.5 * (a.scale + b.scale)) <= 0.02 * std::max(a.scale, b.scale);
        }
        if (!a.valid) a.ramp = b.ramp;  // an order that stops propagating in the band fades out
        if (!b.valid) b.ramp = a.ramp;
        if (!linear) {  // through both halves of the band
            if (!middle.valid) middle.ramp = 0.5 * (a.ramp + b.ramp);
            const OrderRecord& from_record = t < 0.5 ? a : middle;
            const OrderRecord& to_record = t < 0.5 ? middle : b;
            const double h = t < 0.5 ? 2 * t : 2 * t - 1;
            radiance += (from_record.scale + h * (to_record.scale - from_record.scale)) *
                        std::clamp(from_record.ramp + h * (to_record.ramp - from_record.ramp), 0.0, 1.0);
            continue;
        }
        radiance += (a.scale + t * (b.scale - a.scale)) * std::clamp(a.ramp + t * (b.ramp - a.ramp), 0.0, 1.0);
    }
    return radiance;
}

enum class LampMode { AsShader, Exact };

double orders_radiance(const Disc& d, const ShadingInput& in, const ReferenceContext& c, int nm, double offset, LampMode mode = LampMode::AsShader) {
    const optics::GratingOrderModel model = order_model(c);
    const LampView w = lamp_view(d, in, c, offset);
    const bool banded = mode == LampMode::AsShader && lamp_banded(w).first;
    return (banded ? orders_radiance_banded(d, in, model, w, nm, offset) : orders_radiance_exact(d, in, model, w, nm, offset)) * c.number("Lamp");
}

// The coating's irradiance factor (cos θ for a point): Orders sums a flat lamp over its points as
// the GPU does (`truth`: integrates it by an independent rule); the other techniques see a point.
double lamp_irradiance(const Disc& d, const ShadingInput& in, bool orders, bool truth = false) {
    if (!orders || !in.lamp.is_flat()) return std::max(glm::dot(d.n, d.l), 0.0);
    return truth ? flat_lamp_integral(in.lamp, in.position, d.n, d.v, 1.0).lambert : flat_lamp_factors(in.lamp, in.position, d.n, d.v, 1.0, false).lambert;
}

// The float error of the directions (normalisations, dot products, the chord's length: a few 1e-7;
// 2e-6 is generous) can move an order's image edge or an order over the edge of propagation.
// Where the shader's choice between bands and every sample is that close, float may make either.
Sample orders_sample(const Disc& d, const ShadingInput& in, const ReferenceContext& c, int nm, bool want_intensity) {
    const double value = orders_radiance(d, in, c, nm, 0.0);
    if (want_intensity) return {value, 0.0};
    double uncertainty = 0;
    for (const double offset : {-2e-6, 2e-6}) uncertainty = std::max(uncertainty, std::abs(orders_radiance(d, in, c, nm, offset) - value));
    if (lamp_banded(lamp_view(d, in, c, 0.0)).second < 1e-4) uncertainty += std::abs(orders_radiance(d, in, c, nm, 0.0, LampMode::Exact) - value);
    return {value, uncertainty};
}

// The ground truth: every order at every nm (no bands).
Sample orders_sample_exact(const Disc& d, const ShadingInput& in, const ReferenceContext& c, int nm, bool) {
    return {orders_radiance(d, in, c, nm, 0.0, LampMode::Exact), 0.0};
}

// The surroundings through the orders (cd.fx OrdersFS): per band of EnvironmentBand nm, the band's
// samples of S_k × CMF summed, and each propagating order at the band's mean wavelength mirroring the
// weights w_k found in its direction. XYZ before k and Brightness; `slack` (XYZ, any channel) gets
// the change from float-sized moves of the view (an order over the edge of propagation) and the
// weight cube's seams (where GL leaves the texel to the implementation).
spectral::Vec3 orders_surroundings(const Disc& d, const ReferenceContext& c, const SpectralSetup& s, const EnvironmentLookup& environment,
                                   double* slack) {
    const optics::GratingOrderModel model = order_model(c);
    const int per_band = std::max(static_cast<int>(c.number("EnvironmentBand")) / s.steps, 1);
    const auto at = [&](double offset, double* seams) {
        spectral::Vec3 xyz{};
        const glm::dvec3 view(glm::dot(d.v, d.across) + offset, glm::dot(d.v, d.along), glm::dot(d.v, d.n));
        if (view.z <= 0) return xyz;
        for (int start = s.lower; start <= s.upper; start += per_band * s.steps) {
            std::array<glm::dvec3, 3> band{};  // per CMF channel: Σ S_k cmf_c over k
            double nm_sum = 0, count = 0;
            for (int i = 0; i < per_band && start + i * s.steps <= s.upper; ++i) {
                const int nm = start + i * s.steps;
                const spectral::Vec3 cmf = spectral::cmf_value(*s.cmf, s.observer, nm);
                glm::dvec3 spectra;
                for (int k = 0; k < 3; ++k) spectra[k] = environment.spectral_radiance(glm::dvec3(k == 0, k == 1, k == 2), nm);
                for (size_t ch = 0; ch < 3; ++ch) band[ch] += spectra * (cmf[ch] * s.cmf_unit);
                nm_sum += nm;
                ++count;
            }
            const double wavelength = nm_sum / count;
            const auto [range, efficiencies] = propagating(view, wavelength, model);
            for (int m = range.first; m <= range.last; ++m) {
                const auto l = optics::order_incidence(view, m, wavelength, model.spacing_nm);
                if (!l) continue;
                const double efficiency = efficiencies[static_cast<size_t>(m - range.first)];  // includes the reflectance
                double seam = 0;
                const glm::dvec3 w = environment.spectral_weights(l->x * d.across + l->y * d.along + l->z * d.n, &seam);
                for (size_t ch = 0; ch < 3; ++ch) {
                    xyz[ch] += efficiency * glm::dot(w, band[ch]);
                    if (seams) *seams = std::max(*seams, efficiency * seam * (band[ch].x + band[ch].y + band[ch].z));
                }
            }
        }
        return xyz;
    };
    double seams = 0;
    const spectral::Vec3 value = at(0.0, &seams);
    if (slack) {
        *slack = 0;
        for (const double offset : {-2e-6, 2e-6}) {
            const spectral::Vec3 moved = at(offset, nullptr);
            for (size_t ch = 0; ch < 3; ++ch) *slack = std::max(*slack, std::abs(moved[ch] - value[ch]));
        }
        // Each band's seam can add at most this much; there are this many bands.
        *slack += seams * std::ceil((s.upper - s.lower + 1.0) / (per_band * s.steps));
    }
    return value;
}

// The surroundings mirrored in the disc, as the GPU reads its cube map.
CubeSample mirrored_cube(const ShadingInput& in, const ReferenceContext& c) {
    const glm::dvec3 v = glm::normalize(in.camera - in.position), n = glm::normalize(in.normal);
    return c.sample_cube("Environment", 2.0 * glm::dot(n, v) * n - v);
}

// The ground truth of the surroundings through the orders at one wavelength: every propagating
// order at exactly that wavelength (no bands) mirroring the environment's model (the sky's formula,
// the sun a sharp disc, the spectra in double).
double orders_surroundings_exact(const Disc& d, const ReferenceContext& c, const EnvironmentLookup& environment, int nm) {
    const optics::GratingOrderModel model = order_model(c);
    const glm::dvec3 view(glm::dot(d.v, d.across), glm::dot(d.v, d.along), glm::dot(d.v, d.n));
    if (view.z <= 0) return 0.0;
    const auto [range, efficiencies] = propagating(view, nm, model);
    double radiance = 0;
    for (int m = range.first; m <= range.last; ++m)
        if (const auto l = optics::order_incidence(view, m, nm, model.spacing_nm))
            radiance += efficiencies[static_cast<size_t>(m - range.first)] *
                        environment.exact_spectral_radiance(environment.exact_spectral_weights(l->x * d.across + l->y * d.along + l->z * d.n), nm);
    return radiance;
}

// Whether a technique diffracts the scene environment (Orders): where it does and the scene has a
// spectral environment, the lamp is scaled by Lamp, the surroundings are added (spectral radiance, not
// times the light spectrum) and the stand-in cube map is off.
enum class Surroundings { Ignored, Diffracted };

Reference make(Diffraction diffraction, Surroundings surroundings = Surroundings::Ignored, Diffraction exact = nullptr) {
    Reference r;
    r.shade = [diffraction, surroundings](const ShadingInput& in, const ReferenceContext& c) {
        const SpectralSetup s = spectral_setup(c);
        const int light = static_cast<int>(c.number("LightSpectrum")), substrate = static_cast<int>(c.number("SubstrateSpectrum"));
        const double weight = c.number("SubstrateWeight");
        const Disc d = disc(in);
        const bool lamp_scaled = surroundings == Surroundings::Diffracted;
        const std::optional<EnvironmentLookup> surrounding = lamp_scaled ? surroundings_of(c) : std::nullopt;
        const double diffuse = lamp_irradiance(d, in, lamp_scaled) * (lamp_scaled ? c.number("Lamp") : 1.0);
        spectral::Vec3 xyz = integrate(s, false, [&](int nm) {
            return spectral::packed_value(*s.spectra, light, nm) *
                   (diffraction(d, in, c, nm, true).intensity + weight * spectral::packed_value(*s.spectra, substrate, nm) * diffuse);
        });
        if (surrounding) {
            const spectral::Vec3 seen = orders_surroundings(d, c, s, *surrounding, nullptr);
            for (size_t ch = 0; ch < 3; ++ch) xyz[ch] += seen[ch] * output_scale(s);
        }
        std::array<double, 4> rgba = to_rgba(xyz, s.mapping);
        const bool surrounded = surrounding.has_value();
        const glm::dvec4 mirrored = surrounded ? glm::dvec4(0.0) : mirrored_cube(in, c).value * c.number("EnvironmentWeight");
        for (int i = 0; i < 3; ++i) rgba[static_cast<size_t>(i)] += mirrored[i];
        return rgba;
    };
    r.slack = [diffraction, surroundings](const ShadingInput& in, const ReferenceContext& c) {
        const SpectralSetup s = spectral_setup(c);
        const int light = static_cast<int>(c.number("LightSpectrum"));
        const Disc d = disc(in);
        const std::optional<EnvironmentLookup> surrounded = surroundings == Surroundings::Diffracted ? surroundings_of(c) : std::nullopt;
        double seen_slack = 0;
        if (surrounded) orders_surroundings(d, c, s, *surrounded, &seen_slack);
        return colour_uncertainty(s, [&](int nm) { return diffraction(d, in, c, nm, false).uncertainty * spectral::packed_value(*s.spectra, light, nm); }) +
               (surrounded ? seen_slack * kXyzToRgbRowSum * output_scale(s) : mirrored_cube(in, c).seam_spread * c.number("EnvironmentWeight"));
    };
    // The mirrored cube map is read through sRGB decoding and bilinear weights whose precision GL
    // leaves to the implementation (textured.fx's 4e-3), scaled by its weight.
    if (surroundings == Surroundings::Diffracted) {
        // `compare --ground-truth` under a spectral environment or a sized light: the same lamp and
        // substrate, every order at every nm of 360-830 (no lamp bands), and the surroundings without
        // bands from the environment's model.
        r.truth = [exact](const ShadingInput& in, const ReferenceContext& c, unsigned) {
            const std::optional<EnvironmentLookup> environment = surroundings_of(c);
            const SpectralSetup s = every_nm_setup(c);
            const int light = static_cast<int>(c.number("LightSpectrum")), substrate = static_cast<int>(c.number("SubstrateSpectrum"));
            const Disc d = disc(in);
            const double diffuse = lamp_irradiance(d, in, true, true) * c.number("Lamp");
            std::array<double, 4> rgba = to_rgba(integrate(s, true, [&](int nm) {
                return spectral::packed_value(*s.spectra, light, nm) *
                           (exact(d, in, c, nm, true).intensity + c.number("SubstrateWeight") * spectral::packed_value(*s.spectra, substrate, nm) * diffuse) +
                       (environment ? orders_surroundings_exact(d, c, *environment, nm) : 0.0);
            }), s.mapping);
            if (!environment) {  // the mirrored cube map stands in for the surroundings, as in the shader
                const glm::dvec4 mirrored = mirrored_cube(in, c).value * c.number("EnvironmentWeight");
                for (int i = 0; i < 3; ++i) rgba[static_cast<size_t>(i)] += mirrored[i];
            }
            return rgba;
        };
        r.truth_method = "the orders at every nm (no lamp bands) mirroring the lamp and the environment's model (an image: each direction's own uplifted spectrum; no bands, the sun a sharp disc)";
        r.truth_with_sized_light = true;
    }
    r.tolerance_for = [surroundings](const ReferenceContext& c) {
        const bool stand_in_off = surroundings == Surroundings::Diffracted && surroundings_of(c);
        return 5e-5 + (stand_in_off ? 0.0 : 4e-3 * c.number("EnvironmentWeight"));
    };
    r.tolerance = 5e-5;
    r.why = "float32 sums of up to 471 products against double (as for the other spectral effects, measured ~1e-6); "
            "where x = d u / lambda sits on a jump or a steep flank of a diffraction order, the change its float "
            "error (1e-6 relative + 4e-7 d / lambda) can cause is the pixel's slack; the mirrored cube map adds "
            "EnvironmentWeight x 4e-3 (sRGB decoding precision, as textured.fx)";
    return r;
}

}  // namespace

std::map<std::string, Reference> cd_references() {
    std::map<std::string, Reference> all;
    all.emplace("Thesis", make(thesis_sample));
    all.emplace("Grating", make(grating_sample));
    all.emplace("Orders", make(orders_sample, Surroundings::Diffracted, orders_sample_exact));
    return all;
}

}  // namespace fxview::reference
