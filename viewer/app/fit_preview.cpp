#include "app/fit_preview.hpp"

#include <algorithm>
#include <cmath>

namespace fxview::app {

image::FloatImage fit_preview(const fit::BrdfGrid& measured, const fit::BrdfGrid& model, const PreviewOptions& options) {
    const int columns = static_cast<int>(2 * measured.phi_out.size());
    const int rows = static_cast<int>(measured.theta_in.size() * measured.theta_out.size());
    image::FloatImage out(3 * columns, rows, 4);
    const auto shown = [&](double v) {
        return static_cast<float>(std::pow(std::max(v * options.brighten, 0.0), 1.0 / options.gamma));
    };
    for (size_t i = 0; i < measured.theta_in.size(); ++i)
        for (size_t o = 0; o < measured.theta_out.size(); ++o)
            for (size_t p = 0; p < measured.phi_out.size(); ++p) {
                const auto& m = measured.values[measured.index(i, o, p)];
                const auto& f = model.values[model.index(i, o, p)];
                const int y = static_cast<int>(i * measured.theta_out.size() + o);  // θi = 0, θo = 0 at the top
                for (const int x : {static_cast<int>(p), columns - 1 - static_cast<int>(p)})
                    for (int c = 0; c < 3; ++c) {
                        out.pixel(x, y)[c] = shown(m[static_cast<size_t>(c)]);
                        out.pixel(columns + x, y)[c] = shown(f[static_cast<size_t>(c)]);
                        out.pixel(2 * columns + x, y)[c] = shown(std::abs(m[static_cast<size_t>(c)] - f[static_cast<size_t>(c)]));
                    }
                for (int panel = 0; panel < 3; ++panel) {
                    out.pixel(panel * columns + static_cast<int>(p), y)[3] = 1.0f;
                    out.pixel(panel * columns + columns - 1 - static_cast<int>(p), y)[3] = 1.0f;
                }
            }
    return out;
}

}  // namespace fxview::app
