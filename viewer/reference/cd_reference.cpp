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

double orders_radiance(const Disc& d, const ShadingInput& in, const ReferenceContext& c, int nm, double offset) {
    optics::GratingOrderModel model;
    model.spacing_nm = std::max(c.number("TrackSpacing"), 1.0);
    model.zero_order = c.number("ZeroOrder");
    model.pit_fraction = c.number("PitFraction");
    model.reflectance = c.number("Reflectance");
    const glm::dvec3 view(glm::dot(d.v, d.across) + offset, glm::dot(d.v, d.along), glm::dot(d.v, d.n));
    if (view.z <= 0) return 0.0;
    optics::OrderRange range = optics::propagating_orders(view, nm, model.spacing_nm);
    range.first = std::max(range.first, -kMaxOrder);
    range.last = std::min(range.last, kMaxOrder);
    const std::vector<double> efficiencies = optics::order_efficiencies(model, range);
    const double edge = optics::light_edge_chord(std::max(in.light_radius, 0.0) / glm::length(in.light - in.position));
    const double ratio = nm / model.spacing_nm, tracks = std::max(1.0, c.number("Tracks"));
    double radiance = 0;
    for (int m = range.first; m <= range.last; ++m) {
        const auto l = optics::order_incidence(view, m, nm, model.spacing_nm);
        if (!l) continue;
        const glm::dvec3 incidence = l->x * d.across + l->y * d.along + l->z * d.n;
        const double chord = glm::length(incidence - d.l) + offset;
        const double width = ratio / tracks + in.footprint.x + std::abs(m) * ratio * in.footprint.y;
        radiance += efficiencies[static_cast<size_t>(m - range.first)] * optics::sphere_light_radiance(chord, edge, width);
    }
    return radiance;
}

// The float error of the directions (normalisations, dot products, the chord's length: a few 1e-7;
// 2e-6 is generous) can move an order's image edge or an order over the edge of propagation.
Sample orders_sample(const Disc& d, const ShadingInput& in, const ReferenceContext& c, int nm, bool want_intensity) {
    const double value = orders_radiance(d, in, c, nm, 0.0);
    if (want_intensity) return {value, 0.0};
    double uncertainty = 0;
    for (const double offset : {-2e-6, 2e-6}) uncertainty = std::max(uncertainty, std::abs(orders_radiance(d, in, c, nm, offset) - value));
    return {value, uncertainty};
}

// The surroundings mirrored in the disc, as the GPU reads its cube map.
CubeSample environment(const ShadingInput& in, const ReferenceContext& c) {
    const glm::dvec3 v = glm::normalize(in.camera - in.position), n = glm::normalize(in.normal);
    return c.sample_cube("Environment", 2.0 * glm::dot(n, v) * n - v);
}

Reference make(Diffraction diffraction) {
    Reference r;
    r.shade = [diffraction](const ShadingInput& in, const ReferenceContext& c) {
        const SpectralSetup s = spectral_setup(c);
        const int light = static_cast<int>(c.number("LightSpectrum")), substrate = static_cast<int>(c.number("SubstrateSpectrum"));
        const double weight = c.number("SubstrateWeight");
        const Disc d = disc(in);
        const double diffuse = std::max(glm::dot(d.n, d.l), 0.0);
        std::array<double, 4> rgba = to_rgba(integrate(s, false, [&](int nm) {
            return spectral::packed_value(*s.spectra, light, nm) *
                   (diffraction(d, in, c, nm, true).intensity + weight * spectral::packed_value(*s.spectra, substrate, nm) * diffuse);
        }), s.mapping);
        const glm::dvec4 mirrored = environment(in, c).value * c.number("EnvironmentWeight");
        for (int i = 0; i < 3; ++i) rgba[static_cast<size_t>(i)] += mirrored[i];
        return rgba;
    };
    r.slack = [diffraction](const ShadingInput& in, const ReferenceContext& c) {
        const SpectralSetup s = spectral_setup(c);
        const int light = static_cast<int>(c.number("LightSpectrum"));
        const Disc d = disc(in);
        return colour_uncertainty(s, [&](int nm) { return diffraction(d, in, c, nm, false).uncertainty * spectral::packed_value(*s.spectra, light, nm); }) +
               environment(in, c).seam_spread * c.number("EnvironmentWeight");
    };
    // The mirrored cube map is read through sRGB decoding and bilinear weights whose precision GL
    // leaves to the implementation (textured.fx's 4e-3), scaled by its weight.
    r.tolerance_for = [](const ReferenceContext& c) { return 5e-5 + 4e-3 * c.number("EnvironmentWeight"); };
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
    all.emplace("Orders", make(orders_sample));
    return all;
}

}  // namespace fxview::reference
