// The outgoing directions at which brdf-check evaluates a BRDF, and their densities: several sampling
// strategies (cosine-weighted, uniform, half vectors of GGX lobes from broad to 0.3° wide) on
// stratified grids, combined by multiple importance sampling (Veach's power heuristic, β = 2), so that
// diffuse, glossy and sharp lobes and grazing angles are all integrated well. (The balance heuristic
// leaves the broad strategies a share of a sharp lobe that their grids cannot resolve: a 0.3° lobe of
// albedo 0.9 came out 0.8979 with 64² samples a strategy; 0.90004 with the power heuristic.) The GLSL twin is mode 4
// of effects/lib/brdf_grid.glsl; the directions here are the same ones in double precision.
#pragma once
#include <glm/glm.hpp>

#include <array>

namespace fxview::brdf {

// File: the BRDF file's own sampler (a .brdf's isFunc section, docs/effect-format.md), whose
// directions and densities only the GPU knows: they come back from a render (SampleRequest::directions).
enum class SamplingStrategy { Cosine = 0, Uniform = 1, HalfVector = 2, File = 3 };

struct SampleSet {
    SamplingStrategy strategy = SamplingStrategy::Cosine;
    double alpha = 0.1;            // HalfVector: the GGX lobe width
    int side = 64;                 // the stratified grid: side x side cells, a sample in each one's middle
    glm::dvec2 shift{0.0};         // shift of the grid, in [0, 1) (azimuth only: a shift in θ would move midpoints to cell edges)
    double phi_i_degrees = 0.0;    // azimuth of incidence
};

// The strategies combined, in order: cosine, uniform, then GGX half vectors of these widths.
constexpr std::array<double, 6> kSampledLobeWidths = {0.5, 0.2, 0.08, 0.03, 0.012, 0.005};
constexpr int kSamplingStrategies = 2 + static_cast<int>(kSampledLobeWidths.size());
// The file's own sampler, where a check uses it, comes after them.
constexpr int kFileStrategy = kSamplingStrategies;
SampleSet sample_set(int strategy_index, int side, glm::dvec2 shift, double phi_i_degrees);

// Unit vector to the light for incidence θi and azimuth φi (degrees).
glm::dvec3 incident_direction(double theta_degrees, double phi_degrees);
// The direction a set draws from grid cell (a, b) of its grid (not for File); z <= 0 is below the surface (a
// reflected half vector can point there) and counts as a sample of value 0.
glm::dvec3 sampled_direction(const SampleSet& set, const glm::dvec3& l, int a, int b);
// The density (per solid angle) with which the strategy of `strategy_index` draws v.
double strategy_pdf(int strategy_index, const glm::dvec3& l, const glm::dvec3& v);
// What a sample v drawn by strategy k adds, per unit of f·cos θo: the power heuristic's weight over
// the strategy's density, p_k / Σ_j p_j². Summed over every strategy's N samples and divided by N it
// integrates f·cos θo. `file_pdf` is the file's own sampler's density at v where it takes part
// (kFileStrategy), negative where it does not.
double mis_factor(int strategy_index, const glm::dvec3& l, const glm::dvec3& v, double file_pdf = -1.0);

}  // namespace fxview::brdf
