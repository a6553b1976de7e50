// Image-based lighting on the CPU, read from the same tables the GPU samples (render/environment_maps.hpp)
// through GL's filtering rules (cpu_sampler.hpp), in double precision: the reference of
// effects/lib/environment.glsl, written from its documented arithmetic.
#pragma once
#include <functional>
#include <optional>

#include "brdf/models.hpp"
#include "reference/reference.hpp"
#include "render/environment_maps.hpp"

namespace fxview::reference {

class EnvironmentLookup {
public:
    // None where the scene has no environment (its term is then 0, as on the GPU).
    static std::optional<EnvironmentLookup> from(const ReferenceContext& c);

    // Prefiltered radiance towards world direction `d` for `roughness`; `seam` gets the spread of the
    // texels at a cube corner (where GL leaves the texel to the implementation).
    glm::dvec3 radiance(const glm::dvec3& d, double roughness, double* seam = nullptr) const;
    // The mean radiance a GGX lobe of `roughness` gathers for normal n and eye v (environment_pbr.glsl's
    // environment_lobe_radiance: 16 filtered samples weighted by Fresnel with `f0` and masking).
    glm::dvec3 lobe_radiance(const glm::dvec3& n, const glm::dvec3& v, const glm::dvec3& f0, double roughness, double* seam = nullptr) const;
    glm::dvec3 irradiance(const glm::dvec3& n) const;  // E / pi, at least 0
    glm::dvec3 map_irradiance(const glm::dvec3& n) const;  // the same without the disc lights (the SH alone)
    glm::dvec3 dfg(double nv, double roughness) const;  // A, B, G
    // The environment's spectral form (environment_spectral.glsl): whether it has one, the weights of
    // its three spectra towards world direction `d` (bilinear, as the GPU reads them, times the
    // intensity), and spectrum k at `nm` (360-830) as the GPU's float texture holds it.
    bool spectral() const { return maps_->has_spectral_form(); }
    glm::dvec3 spectral_weights(const glm::dvec3& d, double* seam = nullptr) const;
    double spectral_radiance(const glm::dvec3& weights, int nm) const;
    // Ground truths: the weights from the environment's model itself (its discs sharp) and the
    // radiance in double from the spectra as computed, not as the GPU's texture holds them.
    glm::dvec3 exact_spectral_weights(const glm::dvec3& d) const;
    double exact_spectral_radiance(const glm::dvec3& weights, int nm) const;
    // environment_spectral_lobes.glsl: the weights of E(n)/π from the cosine-convolved cube, and the
    // (1/π)-scaled integral of a Phong lobe about the mirror direction of v or a Blinn lobe of exponent
    // `power` by its 32 to 128 filtered directions. `seam` gets how far GL's filtering leaves the weights open:
    // the spread at cube corners and the footprints' spread over 256 (sub-texel precision).
    glm::dvec3 spectral_irradiance(const glm::dvec3& n, double* seam = nullptr) const;
    glm::dvec3 spectral_highlight(const glm::dvec3& n, const glm::dvec3& v, bool blinn, double power, double* seam = nullptr) const;
    // The parts of spectral_highlight: the weights without the disc lights averaged over the cone a
    // sample of `share` steradians stands for (spectral_environment_filtered: the level whose texels
    // cover it, one coarser, two mixed; `seam` the GL filtering's spread before the intensity); the disc
    // lights' 16 points each (world directions, each with the weights its point brings per unit lobe:
    // radiance · solid angle / 16 / π · intensity); a Phong (x) and Blinn (y) lobe's mass above the
    // surface from the table as the GPU samples it.
    glm::dvec3 spectral_filtered(const glm::dvec3& world, double share, double* seam = nullptr) const;
    struct DiscPoint {
        glm::dvec3 direction, weights;
        double disc_radius;  // the angular radius of the disc it lies on
    };
    std::vector<DiscPoint> spectral_disc_points() const;
    glm::dvec2 spectral_lobe_mass(double nv, double power) const;
    double intensity() const { return intensity_; }
    // Ground truth of (1/π) ∫ g(l) w(l) dl over the model's exact weights: `samples` directions drawn by
    // `draw` (a direction and its density for a point of the unit square; a Hammersley set turned by
    // `seed`), none inside a disc light, each disc by its 512-point quadrature.
    using Draw = std::function<glm::dvec3(const glm::dvec2& u, double& density)>;
    glm::dvec3 exact_spectral_integral(const std::function<double(const glm::dvec3&)>& g, const Draw& draw, int samples, unsigned seed) const;
    // The same as a spectrum (360-830 nm at 1 nm) where the directions' spectra are not a sum of the
    // three (an image, `uplifted()`): each direction's own uplifted spectrum integrated.
    std::vector<double> exact_spectral_integral_spectrum(const std::function<double(const glm::dvec3&)>& g, const Draw& draw, int samples,
                                                         unsigned seed) const;
    bool uplifted() const { return spectral() && maps_->unfiltered().spectral->texels_only; }
    // The thin-film transforms of its three spectra (environment:fourier); null without a spectral form.
    const spectral::PackedTexture* spectral_fourier() const { return maps_->spectral_fourier(); }
    // The ground truth of ∫ L(l) f(l) (n·l) dl over the unfiltered environment: Monte Carlo with
    // `samples` directions (half cosine-, half GGX-distributed for `alpha` around n, combined by the
    // balance heuristic; a Hammersley set turned per pixel by `seed`) plus each disc light (the sun)
    // by a 512-point quadrature over it.
    // environment_light.glsl: 32 directions (half cosine-, half GGX(alpha)-distributed, balance
    // heuristic), each reading the prefiltered radiance whose lobe covers its share of the sphere;
    // each disc light through f at its point nearest the mirror direction of the disc shrunk by
    // b²/α'² (b = radius/2, α' = disc_widened_alpha: the disc for a mirror, its centre for a wide lobe),
    // scaled by α²/α'² (a GGX lobe's mean over the disc).
    template <typename Brdf>
    glm::dvec3 light(const brdf::Directions& d, const Brdf& f, double alpha, double* seam = nullptr) const;
    template <typename Brdf>
    glm::dvec3 integral(const brdf::Directions& d, const Brdf& f, double alpha, int samples, unsigned seed) const;

    // exact_spectral_integral's directions: `add(factor, l)` for each, factor = g / density / samples / π
    // (each disc's points by their share of its solid angle); for integrands that vary with the
    // wavelength differently per direction (a rough film's reflectance at each half vector).
    void visit_exact_integral(const std::function<double(const glm::dvec3&)>& g, const Draw& draw, int samples, unsigned seed,
                              const std::function<void(double factor, const glm::dvec3& l)>& add) const;

private:
    const render::EnvironmentMaps* maps_ = nullptr;
    glm::dvec3 unfiltered(const glm::dvec3& world) const;  // bilinear in the radiance without discs
    // Each disc light through f by its 512-point quadrature (the ground truth).
    glm::dvec3 discs(const brdf::Directions& d, const std::function<glm::dvec3(const glm::dvec3&)>& f) const;
    // As environment_light.glsl shades them (see light()).
    glm::dvec3 discs_shaded(const brdf::Directions& d, const std::function<glm::dvec3(const glm::dvec3&)>& f, double alpha) const;
    friend glm::dvec3 metallic_roughness_environment(const EnvironmentLookup&, const brdf::Directions&, const brdf::MetallicRoughness&, bool,
                                                     bool, double*);
    glm::dmat3 rotation_{1.0};
    double intensity_ = 0.0;
};

// environment_facing_normal() of environment.glsl: at a silhouette (n·v < 0.01) the frame with its
// normal bent towards the eye, n·v then about 0.01; else `d` itself.
brdf::Directions environment_facing(const brdf::Directions& d);

// The metallic-roughness BRDF the environment term stands for: brdf.glsl's metallic_roughness with
// its specular part scaled by the multiple-scattering compensation 1 + F0 (1/E(n·v) - 1) when on.
glm::dvec3 metallic_roughness_compensated(const EnvironmentLookup& environment, const brdf::Directions& d, const brdf::MetallicRoughness& m,
                                          bool compensation);

// metallic_roughness_environment() of environment_pbr.glsl; `lobe_sampling` as its LobeSampling.
glm::dvec3 metallic_roughness_environment(const EnvironmentLookup& environment, const brdf::Directions& d, const brdf::MetallicRoughness& m,
                                          bool compensation, bool lobe_sampling = true, double* seam = nullptr);

}  // namespace fxview::reference

#include "reference/environment_integral.hpp"
