// Where the scene's environment radiance comes from, tabulated as a float cube map in linear
// Rec.709/sRGB primaries (scene-referred; 1 is the radiance that lights a white Lambertian surface to 1):
//   studio            a neutral studio: three soft box lights over a grey floor gradient
//   sky[:ELEV[,CCT]]  a clear daylight sky: the CIE standard clear sky (type 12) luminance
//                     distribution, the sun at ELEV degrees (default 35) with the colour of CIE
//                     daylight at CCT kelvin (default 5500), the sky dome the colour of 12000 K daylight
//   furnace           uniform radiance 1 (the white-furnace test)
//   FILE              an equirectangular .hdr/.exr (width twice the height), a cube cross image,
//                     a cube-map .dds, or six face images F1,F2,...,F6 in the order +X -X +Y -Y +Z -Z
// Errors (unknown name, unreadable file, wrong shape) throw fxview::Error naming the source.
#pragma once
#include <array>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/limits.hpp"
#include "lighting/cube_map.hpp"

namespace fxview::lighting {

// A small bright disc (the sun) kept apart from the tabulated radiance: integrated in closed form
// where the radiance is convolved, so that it does not show as blotches of too few samples.
struct DiscLight {
    glm::dvec3 direction{0.0, 1.0, 0.0};  // unit, towards the light
    double angular_radius = 0.0;          // radians
    glm::dvec3 radiance{0.0};             // uniform over the disc
    double solid_angle() const;
    // `count` directions of equal weight over the disc centred on `centre` (the direction, or it
    // turned into another frame): a sunflower (Vogel) spiral, point k at sqrt((k + ½)/count) of the
    // radius, turned by the golden angle; for ground truths, dense enough for lobes narrower than the disc.
    std::vector<glm::dvec3> quadrature(const glm::dvec3& centre, int count = 512) const;
    // The direction nearest to `towards` of the disc of `radius` (towards itself inside it) centred on `centre`.
    static glm::dvec3 nearest(const glm::dvec3& centre, const glm::dvec3& towards, double radius);
};

// A GGX lobe of width alpha averaged over a disc of angular radius rho about the lobe's centre is, in
// the small-angle limit, the peak of a GGX lobe of width sqrt(alpha² + (rho/2)²) (the half vector
// turns half as far as the light): the width that shades a disc through a BRDF evaluated at its centre,
// exact for a mirror (alpha 0) and for lobes much wider than the disc.
double disc_widened_alpha(double alpha, double angular_radius);

// An environment's spectral form (the built-in sky, studio and furnace by their models; an image by
// uplifting its colours, lighting/image_spectral_form.hpp): L(d, λ) = Σ_k w_k(d) S_k(λ)
// for k < 3, each S_k of luminance 1 (CIE 1931: Σ S ȳ = Σ ȳ over 360-830 nm at 1 nm), so that the RGB
// radiance is Σ_k w_k rgb(S_k). The weights are tabulated with the disc lights drawn in: what a mirror
// sees. The spectral techniques (wavelength.fx, thin films, the CD's orders) read it.
struct SpectralForm {
    FloatCube weights;                                // RGB: w_0, w_1, w_2
    std::array<std::vector<double>, 3> spectra;       // 360-830 nm at 1 nm; an unused one is zero
    // The weights towards a direction from the model itself, not the table, the discs sharp: what
    // ground truths integrate (empty for none).
    std::function<glm::dvec3(const glm::dvec3&)> exact;
    // The same apart: the weights without the disc lights, and the discs with their weights as
    // radiance (lobes wider than a mirror's integrate the small bright discs in closed form).
    FloatCube map_weights;
    std::vector<DiscLight> discs;
    // The radiance at `nm` of what `exact` returned; empty: Σ_k w_k S_k(nm). An image's is its
    // colour's own uplifted spectrum, which three spectra cannot hold for every texel.
    std::function<double(const glm::dvec3& exact_weights, int nm)> exact_radiance;
    // An image has no model beyond its texels: ground truths then read map_weights as the GPU reads
    // a cube (seamless bilinear, reference/cpu_sampler.hpp), the disc lights sharp.
    bool texels_only = false;
    // An image's: how far its three spectra are from its texels' uplifted spectra (relative RMS,
    // lighting/image_spectral_form.hpp); 0 for the built-in models.
    double projection_error = 0.0;
    static constexpr int kFirstNm = 360, kLastNm = 830;
};

struct Environment {
    FloatCube radiance;             // without the discs
    std::vector<DiscLight> discs;
    std::optional<SpectralForm> spectral;
    // The radiance with the discs drawn in (supersampled per texel): the background and the mirror.
    FloatCube radiance_with_discs() const;
};

// Image files are read within `limits`: each file within texture-bytes, and all of them, as the
// float radiance they become, within texture-bytes too (checked before each conversion).
Environment make_environment(const std::string& source, int size, const ResourceLimits& limits = {});

// The procedural ones, for tests and the documentation.
glm::vec3 studio_radiance(const glm::dvec3& direction);
struct Sky {
    double sun_elevation_degrees = 35.0;
    double sun_cct = 5500.0;
};
Sky parse_sky(const std::string& source);  // "sky", "sky:ELEV" or "sky:ELEV,CCT"

}  // namespace fxview::lighting
