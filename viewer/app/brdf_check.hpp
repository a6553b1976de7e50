// `fxview brdf-check`: physics checks of any BRDF an effect renders (the BrdfGrid technique of
// effects/lib/brdf_grid.glsl, which every .brdf file gets): directional albedo against θi, integrated
// by multiple importance sampling over several strategies (brdf/direction_sampling.hpp) on two
// stratified grids of different sizes, whose disagreement is the convergence estimate; an energy verdict only
// where the integral converged (else "unresolved", with the reason); reciprocity (the largest
// relative |f(L,V) − f(V,L)|) at several azimuths of incidence; negative and non-finite values.
#pragma once
#include <array>
#include <deque>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "brdf/direction_sampling.hpp"
#include "image/image.hpp"

namespace fxview::app {

// The tiles' layout, as the GLSL lays it out: 45 incidences θi = 1° + 2° t, 9 tiles a row.
constexpr int kGridTilesX = 9, kGridIncidences = 45, kGridRows = (kGridIncidences + kGridTilesX - 1) / kGridTilesX;
double grid_incidence_degrees(int tile);  // θi of tile t: 1° + 2° t
// Samples per strategy and incidence at the first level: a grid of kSampleSide² (refined to 4 and
// 16 times that where the integral has not converged).
constexpr int kSampleSide = 64;

struct SampleRequest {
    brdf::SampleSet set;
    bool swapped = false;
    // Instead of f: each sample's direction v (rgb; z <= 0 below the surface) and the file's own
    // sampler's density for it (alpha), for a file whose sampler takes part (BrdfCheckOptions::file_sampler).
    bool directions = false;
};

// f(l, v) (or f(v, l) when `swapped`) at the directions of a sample set: an image of
// kGridTilesX·set.side × kGridRows·set.side, rows from the top (as read back from GL), alpha 0 where
// the direction is below the surface; or the directions and densities SampleRequest::directions asks for.
using SampleRenderer = std::function<image::FloatImage(const SampleRequest& request)>;

struct BrdfCheckOptions {
    std::vector<double> phi_i_degrees = {0.0, 45.0, 90.0, 135.0};  // azimuths of incidence checked
    bool reciprocity = true;
    // The file defines its own importance sampling (a .brdf's isFunc): one more strategy of the
    // combination, once its density has passed the checks of brdf_check.cpp.
    bool file_sampler = false;
};

struct AlbedoEstimate {
    double incidence_degrees = 0, phi_i_degrees = 0;
    std::array<double, 3> rgb{}, error{};  // error: from the finer grid's difference to the coarser one (brdf_check.cpp)
    bool converged = true;
};

struct BrdfCheck {
    std::vector<AlbedoEstimate> albedo;  // every incidence of the first azimuth, then of the next
    double max_albedo = 0, max_albedo_degrees = 0, max_albedo_phi_degrees = 0;
    // A verdict needs a converged integral: its error below kConvergence (relative to max(1, albedo)),
    // half the energy tolerance.
    static constexpr double kConvergence = 5e-3;
    // More than 1 % above 1 (beyond the estimate's error) is a violation, not quadrature.
    static constexpr double kEnergyTolerance = 0.01;
    enum class Energy { Conserves, Violates, Unresolved } energy = Energy::Conserves;
    bool conserves_energy = true;  // energy == Conserves
    std::string unresolved_reason;  // where and by how much the integral did not converge
    double reciprocity = 0;  // largest |f(L,V) − f(V,L)| / max(|f|), where f is above 1e-6 of its peak and θo < 89.9°
    // Float rounding at grazing angles reaches ~1e-4 for reciprocal models; a real asymmetry is of order 1.
    static constexpr double kReciprocityTolerance = 1e-3;
    bool reciprocal = true;
    double reciprocity_incidence = 0, reciprocity_exitance = 0, reciprocity_azimuth = 0, reciprocity_phi_i = 0;  // degrees, where
    long negative = 0, non_finite = 0, samples = 0;
    std::array<double, 4> non_finite_where{};  // the first non-finite value's θi, φi, θo, φo (degrees)
    bool file_sampling = false;      // the file's own sampler took part in every estimate
    std::string file_sampling_note;  // why it did not, where the file has one
};

const char* energy_verdict(BrdfCheck::Energy energy);  // "conserves", "violates", "unresolved"

// The check as a sequence of renders, so that a viewer can spread it over its frames: render what
// next() asks for and deliver() it, until next() asks for nothing; result() then holds the check.
class BrdfCheckJob {
public:
    explicit BrdfCheckJob(BrdfCheckOptions options = {});
    std::optional<SampleRequest> next();
    void deliver(image::FloatImage image);
    bool done() const { return stage_ == Stage::Done; }
    double progress() const;  // 0 to 1 (refinement of hard integrals comes on top of the estimate)
    int renders_done() const { return renders_done_; }
    const BrdfCheck& result() const { return check_; }

private:
    enum class Stage { Albedo, Reciprocity, Done };
    void start_azimuth();
    void queue_level();
    void advance();  // the stage's renders are in: evaluate them, queue the next ones
    void finish_albedo();
    void finish();
    int strategies() const { return file_sampler_ ? brdf::kSamplingStrategies + 1 : brdf::kSamplingStrategies; }

    BrdfCheckOptions options_;
    BrdfCheck check_;
    Stage stage_ = Stage::Albedo;
    size_t phi_index_ = 0;
    int level_ = 0, renders_done_ = 0;
    double peak_ = 0;
    std::deque<SampleRequest> pending_;
    bool file_sampler_ = false;  // the file's sampler takes part (until a check of it fails)
    std::vector<image::FloatImage> received_, forward_;  // this stage's renders; the azimuth's first-level f(l, v)
    std::vector<brdf::SampleSet> sets_, forward_sets_;
    std::vector<AlbedoEstimate> estimates_;
    std::vector<std::pair<double, double>> unresolved_;  // (incidence, relative error) not converged
};

BrdfCheck check_brdf(const SampleRenderer& render, const BrdfCheckOptions& options = {});

}  // namespace fxview::app
