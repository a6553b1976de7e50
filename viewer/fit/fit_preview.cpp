#include "fit/fit_preview.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace fxview::fit {
namespace {

constexpr float kSeparator = 0.5f;  // mid grey: visible against black data and white highlights
constexpr int kLegendRows = 4;

double mean(const std::array<double, 3>& v) { return (v[0] + v[1] + v[2]) / 3.0; }

// Signed false colour: t in [-1, 1] from blue through black to red.
std::array<float, 3> signed_colour(double t) {
    t = std::clamp(t, -1.0, 1.0);
    return t >= 0 ? std::array<float, 3>{static_cast<float>(t), 0.0f, 0.0f}
                  : std::array<float, 3>{0.0f, static_cast<float>(0.25 * -t), static_cast<float>(-t)};
}

}  // namespace

FitPreview fit_preview(const BrdfGrid& measured, const BrdfGrid& model, const PreviewOptions& options) {
    const int phis = static_cast<int>(measured.phi_out.size());
    const int thetas_in = static_cast<int>(measured.theta_in.size()), thetas_out = static_cast<int>(measured.theta_out.size());
    const int panel = 2 * phis - 1;  // φo = 0 once, in the centre column
    const int width = 3 * panel + 2;
    const int data_rows = thetas_in * thetas_out + (thetas_in - 1);
    FitPreview result{image::FloatImage(width, data_rows + 1 + kLegendRows, 4), 0.0};
    image::FloatImage& out = result.image;
    for (int y = 0; y < out.height; ++y)
        for (int x = 0; x < out.width; ++x) {
            float* px = out.pixel(x, y);
            const bool separator = x == panel || x == 2 * panel + 1 || y >= data_rows ||
                                   (y % (thetas_out + 1) == thetas_out);
            px[0] = px[1] = px[2] = separator ? kSeparator : 0.0f;
            px[3] = 1.0f;
        }

    const auto inside = [&](size_t i, size_t o) {
        return measured.theta_in[i] <= options.limit_deg && measured.theta_out[o] <= options.limit_deg;
    };
    for (size_t i = 0; i < measured.theta_in.size(); ++i)
        for (size_t o = 0; o < measured.theta_out.size(); ++o)
            if (inside(i, o))
                for (size_t p = 0; p < measured.phi_out.size(); ++p)
                    result.difference_scale = std::max(result.difference_scale, std::abs(mean(measured.values[measured.index(i, o, p)]) -
                                                                                          mean(model.values[model.index(i, o, p)])));
    const double scale = result.difference_scale > 0 ? result.difference_scale : 1.0;

    const auto shown = [&](double v) { return static_cast<float>(std::pow(std::max(v * options.brighten, 0.0), 1.0 / options.gamma)); };
    for (size_t i = 0; i < measured.theta_in.size(); ++i)
        for (size_t o = 0; o < measured.theta_out.size(); ++o) {
            const int y = static_cast<int>(i) * (thetas_out + 1) + static_cast<int>(o);  // θi = 0, θo = 0 at the top
            const bool fitted = inside(i, o);
            for (size_t p = 0; p < measured.phi_out.size(); ++p) {
                const auto& m = measured.values[measured.index(i, o, p)];
                const auto& f = model.values[model.index(i, o, p)];
                const std::array<float, 3> difference = signed_colour((mean(m) - mean(f)) / scale);
                for (const int column : {phis - 1 + static_cast<int>(p), phis - 1 - static_cast<int>(p)})
                    for (int c = 0; c < 3; ++c) {
                        float values[3] = {shown(m[static_cast<size_t>(c)]), shown(f[static_cast<size_t>(c)]), difference[static_cast<size_t>(c)]};
                        for (int k = 0; k < 3; ++k) {
                            // Outside the fit: a dim grey version, so that it reads as "not fitted".
                            const float v = fitted ? values[k] : 0.08f + 0.22f * std::min(values[k], 1.0f);
                            out.pixel(k * (panel + 1) + column, y)[c] = v;
                        }
                    }
            }
        }

    // Legend under the difference panel: −scale (blue) at the left, 0 (black) in the centre, +scale (red).
    for (int x = 0; x < panel; ++x) {
        const std::array<float, 3> colour = signed_colour(2.0 * x / (panel - 1) - 1.0);
        for (int y = data_rows + 1; y < out.height; ++y)
            for (int c = 0; c < 3; ++c) out.pixel(2 * (panel + 1) + x, y)[c] = colour[static_cast<size_t>(c)];
    }
    return result;
}

}  // namespace fxview::fit
