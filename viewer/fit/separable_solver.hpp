// The global solver for any model of fit_model.hpp: for a given shape θ the best scales per channel
// are a two-variable bounded least-squares problem solved exactly (its minimum is the "profile" cost
// of θ); θ is searched over its whole range on a log scale (20 points per decade in one dimension,
// 5 per decade in two, then a compass search from the best few grid points), and everything is
// polished together by the bounded Levenberg-Marquardt (bounded_levenberg_marquardt.hpp) with the
// models' analytic derivatives. Large data (a MERL file) are searched on an evenly strided subset;
// the refined minima are ranked again over all samples and the near-tied ones all polished.
#pragma once
#include <array>
#include <functional>
#include <string>
#include <vector>

#include "fit/bounded_levenberg_marquardt.hpp"
#include "fit/fit_model.hpp"

namespace fxview::fit {

// The residual's scale g: g(y) − g(f) is fitted. Linear, cube root or log of (x + ε).
enum class Residual { Linear, CubeRoot, Log };
struct ResidualTransform {
    Residual kind = Residual::Linear;
    double epsilon = 0;
    double value(double x) const;
    double slope(double x) const;
};

// The samples as the solver sees them: geometry, values and the residual weights w_j.
struct FitData {
    std::vector<SampleGeometry> geometry;
    std::vector<std::array<double, 3>> values;
    std::vector<double> weights;
};

struct SeparableSolution {
    std::vector<double> shape;
    std::array<double, 3> a{}, b{};
    double cost = 0;  // Σ (w (g(y) − g(f)))² at the end
    BoundedReport polish;
};

// Progress: fraction 0..1, stage, current shape, scales and cost.
using SeparableProgress =
    std::function<void(double fraction, const char* stage, const std::vector<double>& shape, const std::array<double, 3>& a,
                        const std::array<double, 3>& b, double cost)>;

// The global optimum of the linear-residual least squares (no start), or, with `start`, a polish of
// the `transform`ed residual from there (the compressed and reweighted problems of the caller).
SeparableSolution solve_separable(const FitModel& model, const FitData& data, const ResidualTransform& transform = {},
                                  const SeparableSolution* start = nullptr, const SeparableProgress& progress = {});

// Σ_j Σ_c (w_j (g(y_jc) − g(f_jc)))² of a solution.
double separable_cost(const FitModel& model, const FitData& data, const ResidualTransform& transform, const std::vector<double>& shape,
                      const std::array<double, 3>& a, const std::array<double, 3>& b);

}  // namespace fxview::fit
