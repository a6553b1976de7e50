#include "app/spectrum_plot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "image/canvas.hpp"
#include "image/color_encoding.hpp"

namespace fxview::app {

using image::Canvas;
using image::Rgb;

image::FloatImage plot_spectra(const std::vector<spectral::NamedSpectrum>& spectra, const spectral::Observer& observer,
                               const PlotOptions& o) {
    Canvas canvas(o.width, o.height);
    const int left = 80, right = o.width - 200, top = 30, bottom = o.height - 90;
    double peak = 0;
    for (const auto& s : spectra)
        for (int nm = o.lower_nm; nm <= o.upper_nm; ++nm)
            peak = std::max(peak, o.normalise ? 1.0 : s.spectrum.at(nm));
    const auto axis = image::nice_axis(peak * 1.02);  // not a structured binding: lambdas below capture it (clang 14)
    const double y_max = axis.first, y_step = axis.second;
    const auto px = [&](double nm) { return left + (nm - o.lower_nm) / (o.upper_nm - o.lower_nm) * (right - left); };
    const auto py = [&](double v) { return bottom - v / y_max * (bottom - top); };
    const Rgb grid{0.88f, 0.88f, 0.88f}, ink{0.1f, 0.1f, 0.1f};

    for (double v = 0; v <= y_max + 1e-9; v += y_step) {
        canvas.line(left, static_cast<float>(py(v)), right, static_cast<float>(py(v)), grid, 1.0f);
        const std::string label = image::chart_number(v);
        canvas.text(left - 10 - Canvas::text_width(label), static_cast<int>(py(v)) - 6, label, ink);
    }
    const int first_tick = (o.lower_nm + 49) / 50 * 50;
    for (int nm = first_tick; nm <= o.upper_nm; nm += 50) {
        canvas.line(static_cast<float>(px(nm)), top, static_cast<float>(px(nm)), bottom, grid, 1.0f);
        const std::string label = std::to_string(nm);
        canvas.text(static_cast<int>(px(nm)) - Canvas::text_width(label) / 2, bottom + 30, label, ink);
    }
    // The visible band: each wavelength's colour, desaturated into the sRGB gamut, brightest channel 1.
    for (int x = left; x < right; ++x) {
        const double nm = o.lower_nm + (x - left + 0.5) / (right - left) * (o.upper_nm - o.lower_nm);
        const spectral::Vec3 xyz{observer.x.value(nm), observer.y.value(nm), observer.z.value(nm)};
        spectral::Vec3 rgb = spectral::xyz_to_linear_srgb(xyz, spectral::GamutMapping::Desaturate);
        const double highest = std::max({rgb[0], rgb[1], rgb[2], 1e-9});
        const double brightness = std::min(1.0, xyz[1] * 4);  // fade into the dim ends of the spectrum
        const Rgb c{static_cast<float>(spectral::srgb_encode(rgb[0] / highest * brightness)),
                    static_cast<float>(spectral::srgb_encode(rgb[1] / highest * brightness)),
                    static_cast<float>(spectral::srgb_encode(rgb[2] / highest * brightness))};
        canvas.rect(x, bottom + 4, x + 1, bottom + 20, c);
    }
    canvas.line(left, bottom, right, bottom, ink, 1.5f);
    canvas.line(left, top, left, bottom, ink, 1.5f);
    const std::string x_label = "wavelength / nm";
    canvas.text((left + right - Canvas::text_width(x_label)) / 2, o.height - 30, x_label, ink);
    canvas.text(10, 8, o.normalise ? "relative (peak = 1)" : "value", ink);

    for (size_t i = 0; i < spectra.size(); ++i) {
        const Rgb color = image::palette(i);
        double scale = 1.0;
        if (o.normalise) {
            double own = 0;
            for (int nm = o.lower_nm; nm <= o.upper_nm; ++nm) own = std::max(own, spectra[i].spectrum.at(nm));
            scale = own > 0 ? 1.0 / own : 1.0;
        }
        for (int nm = o.lower_nm; nm < o.upper_nm; ++nm)
            canvas.line(static_cast<float>(px(nm)), static_cast<float>(py(spectra[i].spectrum.at(nm) * scale)),
                        static_cast<float>(px(nm + 1)), static_cast<float>(py(spectra[i].spectrum.at(nm + 1) * scale)), color, 2.0f);
        const int legend_y = top + 10 + static_cast<int>(i) * 24;
        canvas.line(static_cast<float>(right + 20), static_cast<float>(legend_y + 6), static_cast<float>(right + 50),
                    static_cast<float>(legend_y + 6), color, 3.0f);
        canvas.text(right + 58, legend_y, spectra[i].name.substr(0, 14), ink);
    }
    return canvas.take();
}

}  // namespace fxview::app
