#include "app/brdf_plot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "image/canvas.hpp"
#include "image/color_encoding.hpp"

namespace fxview::app {
namespace {

using image::Canvas;
using image::Rgb;

const Rgb kGrid{0.86f, 0.86f, 0.86f}, kInk{0.1f, 0.1f, 0.1f}, kMuted{0.55f, 0.55f, 0.55f};

void legend(Canvas& canvas, const std::vector<BrdfSeries>& series, int x, int y) {
    for (size_t i = 0; i < series.size(); ++i) {
        const int row = y + static_cast<int>(i) * 24;
        canvas.line(static_cast<float>(x), static_cast<float>(row + 6), static_cast<float>(x + 30), static_cast<float>(row + 6), image::palette(i), 3.0f);
        const size_t bad = not_finite(series[i]);
        canvas.text(x + 38, row, series[i].name.substr(0, 28) + (bad ? " (" + std::to_string(bad) + " NaN, not drawn)" : ""), kInk);
    }
}

// A title that wraps at spaces to the canvas's width; returns the y below it.
int title(Canvas& canvas, const std::string& text, int y, Rgb colour) {
    const int width = canvas.width() - 24;
    std::string line;
    size_t at = 0;
    while (at < text.size()) {
        size_t next = text.find(' ', at + 1);
        if (next == std::string::npos) next = text.size();
        const std::string word = text.substr(at, next - at);
        if (!line.empty() && Canvas::text_width(line + word) > width) {
            canvas.text(12, y, line, colour);
            y += 20;
            line = word.substr(word.find_first_not_of(' '));
        } else {
            line += word;
        }
        at = next;
    }
    if (!line.empty()) canvas.text(12, y, line, colour);
    return y + 20;
}

double largest(const std::vector<BrdfSeries>& series) {
    double peak = 0;
    for (const auto& s : series)
        for (const double v : s.values)
            if (std::isfinite(v)) peak = std::max(peak, v);
    return peak;
}

}  // namespace

size_t not_finite(const BrdfSeries& s) {
    return static_cast<size_t>(std::count_if(s.values.begin(), s.values.end(), [](double v) { return !std::isfinite(v); }));
}

image::FloatImage polar_chart(const std::vector<BrdfSeries>& series, double incidence_degrees, bool logarithmic, ChartSize size) {
    Canvas canvas(size.width, size.height);
    const float cx = size.width * 0.5f, cy = static_cast<float>(size.height - 50);
    const float radius = std::max(10.0f, std::min(cx - 30.0f, cy - 70.0f));
    const double peak = largest(series);
    // Linear: radius ∝ f up to a nice maximum. Logarithmic: four decades below the peak's decade.
    const auto axis = image::nice_axis(peak * 1.02);
    const double top = logarithmic ? std::ceil(std::log10(std::max(peak, 1e-30))) : axis.first;
    const double bottom = logarithmic ? top - 4.0 : 0.0;
    const auto to_radius = [&](double f) {
        const double t = logarithmic ? (f > 0 ? (std::log10(f) - bottom) / (top - bottom) : 0.0) : f / axis.first;
        return static_cast<float>(std::clamp(t, 0.0, 1.0) * radius);
    };
    const auto point = [&](double degrees, float r) {
        const double a = degrees * std::numbers::pi / 180.0;
        return std::pair{cx + r * static_cast<float>(std::sin(a)), cy - r * static_cast<float>(std::cos(a))};
    };
    // Rings at the ticks, spokes every 30°.
    std::vector<double> ticks;
    if (logarithmic)
        for (double d = bottom + 1; d <= top + 1e-9; d += 1) ticks.push_back(std::pow(10.0, d));
    else
        for (double v = axis.second; v <= axis.first + 1e-12; v += axis.second) ticks.push_back(v);
    for (const double tick : ticks) {
        const float r = to_radius(tick);
        for (int k = 0; k < 90; ++k) {
            const auto [ax, ay] = point(-90.0 + 2.0 * k, r);
            const auto [bx, by] = point(-88.0 + 2.0 * k, r);
            canvas.line(ax, ay, bx, by, kGrid, 1.0f);
        }
        canvas.text(static_cast<int>(cx + r) - Canvas::text_width(image::chart_number(tick)) / 2, static_cast<int>(cy) + 8,
                    image::chart_number(tick), kMuted);
    }
    for (int degrees = -90; degrees <= 90; degrees += 30) {
        const auto [x, y] = point(degrees, radius);
        canvas.line(cx, cy, x, y, kGrid, 1.0f);
        const auto [lx, ly] = point(degrees, radius + 18);
        const std::string label = std::to_string(degrees);
        canvas.text(static_cast<int>(lx) - Canvas::text_width(label) / 2, static_cast<int>(ly) - 6, label, kMuted);
    }
    canvas.line(cx - radius, cy, cx + radius, cy, kInk, 1.5f);
    // The light's direction on the right.
    const auto [light_x, light_y] = point(incidence_degrees, radius);
    canvas.line(cx, cy, light_x, light_y, Rgb{0.95f, 0.7f, 0.1f}, 2.5f);
    for (size_t i = 0; i < series.size(); ++i) {
        const auto& values = series[i].values;
        const size_t n = values.size();
        for (size_t k = 0; k + 1 < n; ++k) {
            const double d0 = -90.0 + 180.0 * (k + 0.5) / n, d1 = -90.0 + 180.0 * (k + 1.5) / n;
            if (!std::isfinite(values[k]) || !std::isfinite(values[k + 1])) continue;
            const auto [ax, ay] = point(d0, to_radius(values[k]));
            const auto [bx, by] = point(d1, to_radius(values[k + 1]));
            canvas.line(ax, ay, bx, by, image::palette(i), 2.0f);
        }
    }
    const int below = title(canvas, "f(l, v) in the plane of incidence, theta_i = " + image::chart_number(incidence_degrees) + " deg" +
                                        (logarithmic ? " (log scale)" : ""), 10, kInk);
    legend(canvas, series, 12, below + 6);
    return canvas.take();
}

image::FloatImage albedo_chart(const std::vector<BrdfSeries>& series, const std::vector<double>& incidence_degrees, ChartSize size) {
    Canvas canvas(size.width, size.height);
    const int left = 80, right = size.width - 30, top = 70, bottom = size.height - 60;
    const auto axis = image::nice_axis(std::max(1.1, largest(series) * 1.05));
    const auto px = [&](double degrees) { return static_cast<float>(left + degrees / 90.0 * (right - left)); };
    const auto py = [&](double v) { return static_cast<float>(bottom - v / axis.first * (bottom - top)); };
    for (double v = 0; v <= axis.first + 1e-9; v += axis.second) {
        canvas.line(static_cast<float>(left), py(v), static_cast<float>(right), py(v), kGrid, 1.0f);
        const std::string label = image::chart_number(v);
        canvas.text(left - 10 - Canvas::text_width(label), static_cast<int>(py(v)) - 6, label, kInk);
    }
    for (int d = 0; d <= 90; d += 15) {
        canvas.line(px(d), static_cast<float>(top), px(d), static_cast<float>(bottom), kGrid, 1.0f);
        const std::string label = std::to_string(d);
        canvas.text(static_cast<int>(px(d)) - Canvas::text_width(label) / 2, bottom + 10, label, kInk);
    }
    // Energy conservation: no albedo above 1 (dashed in ink, so that no curve's colour hides it).
    for (int k = 0; k < 45; k += 2) canvas.line(px(2.0 * k), py(1.0), px(2.0 * k + 2), py(1.0), kInk, 1.5f);
    canvas.line(static_cast<float>(left), static_cast<float>(bottom), static_cast<float>(right), static_cast<float>(bottom), kInk, 1.5f);
    canvas.line(static_cast<float>(left), static_cast<float>(top), static_cast<float>(left), static_cast<float>(bottom), kInk, 1.5f);
    for (size_t i = 0; i < series.size(); ++i)
        for (size_t k = 0; k + 1 < series[i].values.size() && k + 1 < incidence_degrees.size(); ++k)
            canvas.line(px(incidence_degrees[k]), py(series[i].values[k]), px(incidence_degrees[k + 1]), py(series[i].values[k + 1]),
                        image::palette(i), 2.0f);
    const std::string x_label = "angle of incidence / deg";
    canvas.text((left + right - Canvas::text_width(x_label)) / 2, size.height - 28, x_label, kInk);
    const int below = title(canvas, "directional albedo (mean of R, G, B); dashed: 1, what the light brings", 10, kInk);
    legend(canvas, series, left + 20, below + 6);
    return canvas.take();
}

image::FloatImage lobe_chart(const image::FloatImage& hemisphere, const std::string& name, double incidence_degrees, ChartSize size) {
    Canvas canvas(size.width, size.height);
    const int columns = hemisphere.width, rows = hemisphere.height;
    const auto value = [&](int a, int b) {  // b counts θo from 0 (the bottom row)
        const float* p = hemisphere.pixel(a, rows - 1 - b);
        const double f = (static_cast<double>(p[0]) + p[1] + p[2]) / 3.0;
        return std::isfinite(f) ? std::max(f, 0.0) : 0.0;
    };
    double peak = 0;
    for (int b = 0; b < rows; ++b)
        for (int a = 0; a < columns; ++a) peak = std::max(peak, value(a, b));
    if (!(peak > 0)) peak = 1;
    // Seen from azimuth -60° and 25° above the surface, orthographically.
    const double azimuth = -60.0 * std::numbers::pi / 180.0, elevation = 25.0 * std::numbers::pi / 180.0;
    const float scale = 0.42f * std::min(size.width, size.height), cx = size.width * 0.5f, cy = size.height * 0.68f;
    const auto project = [&](double x, double y, double z) {
        const double u = x * std::cos(azimuth) - y * std::sin(azimuth);
        const double depth = x * std::sin(azimuth) + y * std::cos(azimuth);
        const double w = z * std::cos(elevation) - depth * std::sin(elevation);
        return std::pair{cx + scale * static_cast<float>(u), cy - scale * static_cast<float>(w)};
    };
    const auto surface = [&](int a, int b) {
        const double phi = 2.0 * std::numbers::pi * (a + 0.5) / columns, theta = 0.5 * std::numbers::pi * (b + 0.5) / rows;
        const double r = value(a % columns, b) / peak;
        return project(r * std::sin(theta) * std::cos(phi), r * std::sin(theta) * std::sin(phi), r * std::cos(theta));
    };
    // The surface's unit circle and the light's direction.
    for (int k = 0; k < 72; ++k) {
        const double p0 = 2.0 * std::numbers::pi * k / 72, p1 = 2.0 * std::numbers::pi * (k + 1) / 72;
        const auto [ax, ay] = project(std::cos(p0), std::sin(p0), 0.0);
        const auto [bx, by] = project(std::cos(p1), std::sin(p1), 0.0);
        canvas.line(ax, ay, bx, by, kGrid, 1.0f);
    }
    const double ti = incidence_degrees * std::numbers::pi / 180.0;
    const auto [ox, oy] = project(0, 0, 0);
    const auto [lx, ly] = project(std::sin(ti), 0.0, std::cos(ti));
    canvas.line(ox, oy, lx, ly, Rgb{0.95f, 0.7f, 0.1f}, 2.5f);
    const Rgb ink = image::palette(0);
    for (int b = 0; b < rows; b += std::max(1, rows / 12))
        for (int a = 0; a < columns; ++a) {
            const auto [ax, ay] = surface(a, b);
            const auto [bx, by] = surface(a + 1, b);
            canvas.line(ax, ay, bx, by, ink, 1.0f);
        }
    for (int a = 0; a < columns; a += std::max(1, columns / 24))
        for (int b = 0; b + 1 < rows; ++b) {
            const auto [ax, ay] = surface(a, b);
            const auto [bx, by] = surface(a, b + 1);
            canvas.line(ax, ay, bx, by, ink, 1.0f);
        }
    const int below = title(canvas, name + ": f over the hemisphere, theta_i " + image::chart_number(incidence_degrees) + " deg", 10, kInk);
    title(canvas, "radius f / " + image::chart_number(peak) + "; light in yellow", below + 2, kMuted);
    return canvas.take();
}

image::FloatImage slice_chart(const image::FloatImage& scaled, float white, double phi_d_degrees, ChartSize size) {
    Canvas canvas(size.width, size.height);
    const int left = kSliceMargins.left, top = kSliceMargins.top;
    const int right = left + scaled.width, bottom = top + scaled.height;
    // The slice itself: its linear values (1 = white) drawn as they are.
    for (int y = 0; y < scaled.height; ++y)
        for (int x = 0; x < scaled.width; ++x) {
            const float* p = scaled.pixel(x, y);
            const auto encode = [](float v) { return image::srgb_encode(std::clamp(std::isfinite(v) ? v : 0.0f, 0.0f, 1.0f)); };
            canvas.put(left + x, top + y, Rgb{encode(p[0]), encode(p[1]), encode(p[2])}, 1.0f);
        }
    // Axes: θh across, θd up, ticks every 15°.
    for (int d = 0; d <= 90; d += 15) {
        const float x = static_cast<float>(left + d / 90.0 * scaled.width), y = static_cast<float>(bottom - d / 90.0 * scaled.height);
        canvas.line(x, static_cast<float>(bottom), x, static_cast<float>(bottom + 5), kInk, 1.0f);
        canvas.line(static_cast<float>(left - 5), y, static_cast<float>(left), y, kInk, 1.0f);
        const std::string label = std::to_string(d);
        canvas.text(static_cast<int>(x) - Canvas::text_width(label) / 2, bottom + 8, label, kInk);
        canvas.text(left - 8 - Canvas::text_width(label), static_cast<int>(y) - 6, label, kInk);
    }
    canvas.text((left + right - Canvas::text_width("theta_h / deg")) / 2, bottom + 26, "theta_h / deg", kInk);
    canvas.text(4, top - 20, "theta_d / deg", kInk);
    // The colour bar: 0 at the bottom to `white` at the top.
    const int bar = right + 20;
    for (int y = top; y < bottom; ++y) {
        const float v = image::srgb_encode(static_cast<float>(bottom - y) / static_cast<float>(bottom - top));
        canvas.rect(bar, y, bar + 16, y + 1, Rgb{v, v, v});
    }
    for (const double t : {0.0, 0.5, 1.0}) {
        const int y = static_cast<int>(bottom - t * (bottom - top));
        char label[32];
        std::snprintf(label, sizeof label, "%.3g", t * white);
        canvas.text(bar + 20, y - 6, label, kInk);
    }
    char caption[96];
    std::snprintf(caption, sizeof caption, "f at phi_d = %g deg", phi_d_degrees);  // the scale's meaning: on stdout and in the docs
    title(canvas, caption, 4, kInk);
    return canvas.take();
}

float scale_slice_for_display(image::FloatImage& slice) {
    std::vector<float> values;
    for (int y = 0; y < slice.height; ++y)
        for (int x = 0; x < slice.width; ++x)
            if (std::isfinite(slice.pixel(x, y)[1])) values.push_back(slice.pixel(x, y)[1]);
    if (values.empty()) return 0.0f;
    const auto percentile = values.begin() + static_cast<std::ptrdiff_t>(values.size() * 99 / 100);
    std::nth_element(values.begin(), percentile, values.end());
    const float white = *percentile;
    if (!(white > 0)) return 0.0f;
    for (int y = 0; y < slice.height; ++y)
        for (int x = 0; x < slice.width; ++x)
            for (int c = 0; c < 3; ++c) slice.pixel(x, y)[c] /= white;
    return white;
}

}  // namespace fxview::app
