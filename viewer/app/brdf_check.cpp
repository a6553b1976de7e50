#include "app/brdf_check.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "core/error.hpp"

namespace fxview::app {

double grid_incidence_degrees(int tile) { return 1.0 + 2.0 * tile; }

const char* energy_verdict(BrdfCheck::Energy energy) {
    switch (energy) {
        case BrdfCheck::Energy::Conserves: return "conserves";
        case BrdfCheck::Energy::Violates: return "violates";
        case BrdfCheck::Energy::Unresolved: break;
    }
    return "unresolved";
}

namespace {

// Each level renders two grids: midpoints of side² cells, and of (3/4 side)² cells turned in
// azimuth. The first grid's error is taken as 3 times their difference: right if it falls as 1/side
// (side/(3/4 side) − 1 = 1/3: features smaller than a cell, a jump at the horizon), cautious where it
// falls as 1/side² (smooth integrands; a 0.3° lobe measured 0.900092, 0.900045, 0.899994, 0.899978 at
// sides 48, 64, 128, 1024 for a truth of 0.89998). Incidences whose integral has not converged are
// refined at the next level (4 times the samples), up to the last.
constexpr std::array<int, 3> kLevelSides = {kSampleSide, 2 * kSampleSide, 4 * kSampleSide};
constexpr double kReciprocityHorizon = 5e-3;  // cos θo below which reciprocity is not compared (θo > 89.7°)

brdf::SampleSet grid_set(int strategy, int level, int grid, double phi_i) {
    const int side = grid == 0 ? kLevelSides[static_cast<size_t>(level)] : kLevelSides[static_cast<size_t>(level)] * 3 / 4;
    const glm::dvec2 shift = grid == 0 ? glm::dvec2(0.0) : glm::dvec2(0.0, 0.3819660112501051 / side);  // golden-ratio turn
    return brdf::sample_set(strategy, side, shift, phi_i);
}

// Pixel (a, b) of tile `tile` in a render whose tiles are image.width / kGridTilesX wide.
const float* sample_at(const image::FloatImage& image, int tile, int a, int b) {
    const int side = image.width / kGridTilesX;
    const int x = (tile % kGridTilesX) * side + a, gl_y = (tile / kGridTilesX) * side + b;
    return image.pixel(x, image.height - 1 - gl_y);  // GL's row 0 is the image's last row
}

// θo and φo of a direction, degrees.
std::array<double, 2> polar_degrees(const glm::dvec3& v) {
    const double azimuth = std::atan2(v.y, v.x) * 180.0 / std::numbers::pi;
    return {std::acos(std::clamp(v.z, -1.0, 1.0)) * 180.0 / std::numbers::pi, azimuth < 0 ? azimuth + 360.0 : azimuth};
}

// Counts negative and non-finite values (naming the first non-finite one's directions), finds the
// largest |f| (for reciprocity's threshold).
void scan(const image::FloatImage& image, const brdf::SampleSet& set, BrdfCheck& check, double& peak) {
    for (int tile = 0; tile < kGridIncidences; ++tile)
        for (int b = 0; b < set.side; ++b)
            for (int a = 0; a < set.side; ++a) {
                const float* f = sample_at(image, tile, a, b);
                if (f[3] == 0.0f) continue;  // below the surface
                ++check.samples;
                if (!std::isfinite(f[0]) || !std::isfinite(f[1]) || !std::isfinite(f[2])) {
                    if (check.non_finite++ == 0) {
                        const glm::dvec3 l = brdf::incident_direction(grid_incidence_degrees(tile), set.phi_i_degrees);
                        const auto [theta_o, phi_o] = polar_degrees(glm::normalize(brdf::sampled_direction(set, l, a, b)));
                        check.non_finite_where = {grid_incidence_degrees(tile), set.phi_i_degrees, theta_o, phi_o};
                    }
                    continue;
                }
                if (std::min({f[0], f[1], f[2]}) < 0.0f) ++check.negative;
                peak = std::max({peak, std::abs(static_cast<double>(f[0])), std::abs(static_cast<double>(f[1])), std::abs(static_cast<double>(f[2]))});
            }
}

// The albedo of one tile from one grid's renders (one per strategy): Σ f cos θo p_k / Σ_j p_j² over
// every strategy's N samples, over N (the power heuristic; a sample below the surface adds 0). With
// `use_file`, the file's own sampler is one of the strategies: its directions and its density at every
// sample come from `densities` (SampleRequest::directions); without, its samples are left out.
std::array<double, 3> albedo_of(const std::vector<image::FloatImage>& renders, const std::vector<image::FloatImage>& densities,
                                const std::vector<brdf::SampleSet>& sets, int tile, bool use_file) {
    const glm::dvec3 l = brdf::incident_direction(grid_incidence_degrees(tile), sets.front().phi_i_degrees);
    std::array<double, 3> sum{};
    for (size_t k = 0; k < renders.size(); ++k) {
        const brdf::SampleSet& set = sets[k];
        const bool file = set.strategy == brdf::SamplingStrategy::File;
        if (file && !use_file) continue;
        for (int b = 0; b < set.side; ++b)
            for (int a = 0; a < set.side; ++a) {
                const float* f = sample_at(renders[k], tile, a, b);
                if (f[3] == 0.0f || !std::isfinite(f[0]) || !std::isfinite(f[1]) || !std::isfinite(f[2])) continue;
                const float* d = use_file ? sample_at(densities[k], tile, a, b) : nullptr;
                glm::dvec3 v = file ? glm::dvec3(d[0], d[1], d[2]) : brdf::sampled_direction(set, l, a, b);
                if (v.z <= 0) continue;
                v = glm::normalize(v);
                const double weight = v.z * brdf::mis_factor(static_cast<int>(k), l, v, use_file ? static_cast<double>(d[3]) : -1.0);
                for (int c = 0; c < 3; ++c) sum[static_cast<size_t>(c)] += f[c] * weight;
            }
    }
    const double n = static_cast<double>(sets.front().side) * sets.front().side;
    for (double& x : sum) x /= n;
    return sum;
}

// ∫ p dω over the hemisphere of the file's density p at one tile, from one grid's direction renders,
// by the built-in strategies alone (the power heuristic, as albedo_of).
double density_integral(const std::vector<image::FloatImage>& densities, const std::vector<brdf::SampleSet>& sets, int tile) {
    const glm::dvec3 l = brdf::incident_direction(grid_incidence_degrees(tile), sets.front().phi_i_degrees);
    double sum = 0;
    for (int k = 0; k < brdf::kSamplingStrategies; ++k)
        for (int b = 0; b < sets[static_cast<size_t>(k)].side; ++b)
            for (int a = 0; a < sets[static_cast<size_t>(k)].side; ++a) {
                const float* d = sample_at(densities[static_cast<size_t>(k)], tile, a, b);
                if (d[2] > 0.0f) sum += d[3] * brdf::mis_factor(k, l, glm::normalize(glm::dvec3(d[0], d[1], d[2])));
            }
    return sum / (static_cast<double>(sets.front().side) * sets.front().side);
}

// What is wrong with the file's sampling density, from both grids' direction renders: a value that is
// negative or not a number, or more than a whole over the hemisphere where the built-in strategies
// integrate it to within their error; "" if nothing.
std::string density_problem(const std::array<std::vector<image::FloatImage>, 2>& densities, const std::array<std::vector<brdf::SampleSet>, 2>& sets) {
    char text[256];
    for (int tile = 0; tile < kGridIncidences; ++tile) {
        for (size_t k = 0; k < densities[0].size(); ++k)
            for (int b = 0; b < sets[0][k].side; ++b)
                for (int a = 0; a < sets[0][k].side; ++a) {
                    const float* d = sample_at(densities[0][k], tile, a, b);
                    if (d[2] <= 0.0f || (std::isfinite(d[3]) && d[3] >= 0.0f)) continue;  // below the surface, or fine
                    const auto [theta_o, phi_o] = polar_degrees(glm::normalize(glm::dvec3(d[0], d[1], d[2])));
                    std::snprintf(text, sizeof text, "pdfBRDF is %g at theta_i %.0f, theta_o %.1f, phi_o %.1f deg", d[3], grid_incidence_degrees(tile),
                                  theta_o, phi_o);
                    return text;
                }
        const double integral = density_integral(densities[0], sets[0], tile), error = 3.0 * std::abs(integral - density_integral(densities[1], sets[1], tile));
        // A density gives at most 1; 2 % beyond the estimate's error (the albedo's energy tolerance, doubled).
        if (integral - error > 1.02) {
            std::snprintf(text, sizeof text, "pdfBRDF integrates to %.3f +- %.1e over the hemisphere at theta_i %.0f deg (a density gives at most 1)",
                          integral, error, grid_incidence_degrees(tile));
            return text;
        }
    }
    return "";
}

void find_reciprocity(const std::vector<image::FloatImage>& forward, const std::vector<image::FloatImage>& swapped,
                      const std::vector<brdf::SampleSet>& sets, double peak, BrdfCheck& check) {
    for (int k = 0; k < brdf::kSamplingStrategies; ++k) {
        const brdf::SampleSet& set = sets[static_cast<size_t>(k)];
        for (int tile = 0; tile < kGridIncidences; ++tile) {
            const glm::dvec3 l = brdf::incident_direction(grid_incidence_degrees(tile), set.phi_i_degrees);
            for (int b = 0; b < set.side; ++b)
                for (int a = 0; a < set.side; ++a) {
                    const float* f = sample_at(forward[static_cast<size_t>(k)], tile, a, b);
                    const float* g = sample_at(swapped[static_cast<size_t>(k)], tile, a, b);
                    if (f[3] == 0.0f) continue;
                    // Within 0.3° of the horizon float's rounding of the directions (1e-7 in n·v of
                    // 5e-3), amplified by 1/(n·v) terms and sharp exponents, moves f by more than the
                    // tolerance without any asymmetry of the model (Ashikhmin-Shirley: 1.05e-3 at
                    // θi 89°, θo 89.9°); a real asymmetry is of order 1 everywhere else.
                    const glm::dvec3 v = glm::normalize(brdf::sampled_direction(set, l, a, b));
                    if (v.z < kReciprocityHorizon) continue;
                    for (int c = 0; c < 3; ++c) {
                        if (!std::isfinite(f[c]) || !std::isfinite(g[c])) continue;
                        const double larger = std::max(std::abs(f[c]), std::abs(g[c]));
                        if (larger <= 1e-6 * peak) continue;
                        const double relative = std::abs(f[c] - g[c]) / larger;
                        if (relative <= check.reciprocity) continue;
                        const auto [theta_o, phi_o] = polar_degrees(v);
                        check.reciprocity = relative;
                        check.reciprocity_incidence = grid_incidence_degrees(tile);
                        check.reciprocity_exitance = theta_o;
                        check.reciprocity_azimuth = phi_o;
                        check.reciprocity_phi_i = set.phi_i_degrees;
                    }
                }
        }
    }
}

}  // namespace

BrdfCheckJob::BrdfCheckJob(BrdfCheckOptions options) : options_(std::move(options)), file_sampler_(options_.file_sampler) {
    if (options_.phi_i_degrees.empty()) throw UsageError("brdf-check: no azimuth of incidence to check");
    start_azimuth();
}

void BrdfCheckJob::start_azimuth() {
    level_ = 0;
    peak_ = 0;
    estimates_.assign(static_cast<size_t>(kGridIncidences), AlbedoEstimate{});
    queue_level();
}

void BrdfCheckJob::queue_level() {
    stage_ = Stage::Albedo;
    const double phi_i = options_.phi_i_degrees[phi_index_];
    for (int grid = 0; grid < 2; ++grid) {
        for (int k = 0; k < strategies(); ++k) pending_.push_back({grid_set(k, level_, grid, phi_i), false});
        if (file_sampler_)
            for (int k = 0; k < strategies(); ++k) pending_.push_back({grid_set(k, level_, grid, phi_i), false, true});
    }
}

std::optional<SampleRequest> BrdfCheckJob::next() {
    while (pending_.empty() && stage_ != Stage::Done) advance();
    if (stage_ == Stage::Done) return std::nullopt;
    return pending_.front();
}

void BrdfCheckJob::deliver(image::FloatImage image) {
    if (pending_.empty()) throw Error("brdf-check: a render that was not asked for");
    const SampleRequest request = pending_.front();
    pending_.pop_front();
    if (image.width != kGridTilesX * request.set.side || image.height != kGridRows * request.set.side)
        throw Error("brdf-check: a sample image has the wrong size");
    if ((level_ == 0 || request.swapped) && !request.directions && request.set.strategy != brdf::SamplingStrategy::File)
        scan(image, request.set, check_, peak_);
    ++renders_done_;
    received_.push_back(std::move(image));
    sets_.push_back(request.set);
}

double BrdfCheckJob::progress() const {
    if (stage_ == Stage::Done) return 1.0;
    // By azimuths, each counted as its first level and its swapped renders (refinement is extra).
    const double per_azimuth = brdf::kSamplingStrategies * (options_.reciprocity ? 3.0 : 2.0);
    return std::min(0.99, (phi_index_ + std::min(1.0, static_cast<double>(received_.size() + (stage_ == Stage::Reciprocity ? 2 * brdf::kSamplingStrategies : 0)) / per_azimuth)) /
                              options_.phi_i_degrees.size());
}

void BrdfCheckJob::advance() {
    if (stage_ == Stage::Albedo) {
        // Per grid: the strategies' f renders, then (with the file's sampler) their direction renders.
        const auto S = static_cast<size_t>(strategies()), B = file_sampler_ ? 2 * S : S;
        std::array<std::vector<image::FloatImage>, 2> values, densities;
        std::array<std::vector<brdf::SampleSet>, 2> sets;
        for (size_t g = 0; g < 2; ++g) {
            const auto at = [&](size_t i) { return received_.begin() + static_cast<std::ptrdiff_t>(g * B + i); };
            values[g].assign(std::make_move_iterator(at(0)), std::make_move_iterator(at(S)));
            if (file_sampler_) densities[g].assign(std::make_move_iterator(at(S)), std::make_move_iterator(at(2 * S)));
            sets[g].assign(sets_.begin() + static_cast<std::ptrdiff_t>(g * B), sets_.begin() + static_cast<std::ptrdiff_t>(g * B + S));
        }
        // The value and error estimate of a tile, with or without the file's sampler.
        const auto estimate = [&](int tile, bool use_file, std::array<double, 3>& value, std::array<double, 3>& error) {
            const auto a = albedo_of(values[0], densities[0], sets[0], tile, use_file), b = albedo_of(values[1], densities[1], sets[1], tile, use_file);
            for (size_t c = 0; c < 3; ++c) {
                value[c] = a[c];
                error[c] = 3.0 * std::abs(a[c] - b[c]);
            }
        };
        if (file_sampler_) {
            // The file's density must be one, and its estimate must agree with the built-in strategies'
            // alone (which need nothing of the file): a density that is not the sampler's own biases it.
            std::string problem = density_problem(densities, sets);
            for (int tile = 0; tile < kGridIncidences && problem.empty(); ++tile) {
                std::array<double, 3> with{}, with_error{}, without{}, without_error{};
                estimate(tile, true, with, with_error);
                estimate(tile, false, without, without_error);
                // Judged where the built-in strategies converge (elsewhere their error estimate is no bound).
                for (size_t c = 0; c < 3 && problem.empty(); ++c)
                    if (without_error[c] <= BrdfCheck::kConvergence * std::max(1.0, std::abs(without[c])) &&
                        std::abs(with[c] - without[c]) > 3.0 * (with_error[c] + without_error[c]) + 1e-3 * std::max(1.0, std::abs(without[c]))) {
                        char text[256];
                        std::snprintf(text, sizeof text, "with it the albedo at theta_i %.0f deg is %.4f, with the built-in strategies alone %.4f +- %.1e",
                                      grid_incidence_degrees(tile), with[c], without[c], without_error[c]);
                        problem = text;
                    }
            }
            if (!problem.empty()) {
                file_sampler_ = false;
                check_.file_sampling_note = "the file's importance sampling (isFunc) is not used: " + problem;
            }
        }
        bool all_converged = true;
        for (int tile = 0; tile < kGridIncidences; ++tile) {
            AlbedoEstimate& e = estimates_[static_cast<size_t>(tile)];
            if (level_ > 0 && e.converged) continue;
            estimate(tile, file_sampler_, e.rgb, e.error);
            e.incidence_degrees = grid_incidence_degrees(tile);
            e.phi_i_degrees = options_.phi_i_degrees[phi_index_];
            double relative = 0;
            for (size_t c = 0; c < 3; ++c) relative = std::max(relative, e.error[c] / std::max(1.0, std::abs(e.rgb[c])));
            e.converged = relative <= BrdfCheck::kConvergence;
            all_converged = all_converged && e.converged;
        }
        if (level_ == 0) {
            forward_.assign(std::make_move_iterator(values[0].begin()), std::make_move_iterator(values[0].begin() + brdf::kSamplingStrategies));
            forward_sets_.assign(sets[0].begin(), sets[0].begin() + brdf::kSamplingStrategies);
        }
        received_.clear();
        sets_.clear();
        if (!all_converged && level_ + 1 < static_cast<int>(kLevelSides.size())) {
            ++level_;
            queue_level();
            return;
        }
        finish_albedo();
        if (options_.reciprocity) {
            stage_ = Stage::Reciprocity;
            for (const brdf::SampleSet& set : forward_sets_) pending_.push_back({set, true});
            return;
        }
    } else if (stage_ == Stage::Reciprocity) {
        find_reciprocity(forward_, received_, forward_sets_, peak_, check_);
        received_.clear();
        sets_.clear();
    }
    forward_.clear();
    if (++phi_index_ < options_.phi_i_degrees.size()) {
        start_azimuth();
        return;
    }
    finish();
}

void BrdfCheckJob::finish_albedo() {
    for (const AlbedoEstimate& e : estimates_) {
        if (!e.converged) {
            double relative = 0;
            for (size_t c = 0; c < 3; ++c) relative = std::max(relative, e.error[c] / std::max(1.0, std::abs(e.rgb[c])));
            unresolved_.emplace_back(e.incidence_degrees, relative);
        }
        const double largest = std::max({e.rgb[0], e.rgb[1], e.rgb[2]});
        if (largest > check_.max_albedo) {
            check_.max_albedo = largest;
            check_.max_albedo_degrees = e.incidence_degrees;
            check_.max_albedo_phi_degrees = e.phi_i_degrees;
        }
        // A violation needs a converged integral that exceeds 1 by more than the tolerance and its error.
        for (size_t c = 0; c < 3; ++c)
            if (e.converged && e.rgb[c] - e.error[c] > 1.0 + BrdfCheck::kEnergyTolerance) check_.energy = BrdfCheck::Energy::Violates;
        check_.albedo.push_back(e);
    }
}

void BrdfCheckJob::finish() {
    stage_ = Stage::Done;
    if (check_.energy != BrdfCheck::Energy::Violates && !unresolved_.empty()) {
        check_.energy = BrdfCheck::Energy::Unresolved;
        std::sort(unresolved_.begin(), unresolved_.end());
        double worst = 0;
        for (const auto& u : unresolved_) worst = std::max(worst, u.second);
        char text[320];
        std::snprintf(text, sizeof text,
                      "the albedo integral did not converge at %zu of %zu incidences (theta_i %.0f-%.0f deg) with %d samples a strategy "
                      "(its error estimate reaches %.2g of the value): a lobe too sharp or a value too irregular there",
                      unresolved_.size(), check_.albedo.size(), unresolved_.front().first, unresolved_.back().first,
                      kLevelSides.back() * kLevelSides.back(), worst);
        check_.unresolved_reason = text;
    }
    check_.conserves_energy = check_.energy == BrdfCheck::Energy::Conserves;
    check_.file_sampling = file_sampler_;
    check_.reciprocal = check_.reciprocity <= BrdfCheck::kReciprocityTolerance;
}

BrdfCheck check_brdf(const SampleRenderer& render, const BrdfCheckOptions& options) {
    BrdfCheckJob job(options);
    while (const auto request = job.next()) job.deliver(render(*request));
    return job.result();
}

}  // namespace fxview::app
