#include "app/spectrum_plot.hpp"

#include <stb/stb_easy_font.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "image/color_encoding.hpp"

namespace fxview::app {
namespace {

struct Rgb {
    float r, g, b;
};

// Drawing in sRGB-encoded values (what the eye sees), converted to linear when stored, so that
// the PNG writer's encoding gives back exactly these colours.
class Canvas {
public:
    Canvas(int width, int height) : image_(width, height, 4) {
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x) put(x, y, {1, 1, 1}, 1.0f);
    }
    void put(int x, int y, Rgb c, float coverage) {
        if (x < 0 || y < 0 || x >= image_.width || y >= image_.height || coverage <= 0) return;
        float* p = image_.pixel(x, y);
        const float a = std::min(coverage, 1.0f);
        const float encoded[3] = {c.r, c.g, c.b};
        for (int k = 0; k < 3; ++k) {
            const float current = image::srgb_encode(p[k]);
            p[k] = image::srgb_decode(current + (encoded[k] - current) * a);
        }
        p[3] = 1.0f;
    }
    void rect(int x0, int y0, int x1, int y1, Rgb c) {
        for (int y = y0; y < y1; ++y)
            for (int x = x0; x < x1; ++x) put(x, y, c, 1.0f);
    }
    // Anti-aliased line of the given width: coverage from the distance to the segment.
    void line(float ax, float ay, float bx, float by, Rgb c, float width) {
        const int x0 = static_cast<int>(std::floor(std::min(ax, bx) - width)), x1 = static_cast<int>(std::ceil(std::max(ax, bx) + width));
        const int y0 = static_cast<int>(std::floor(std::min(ay, by) - width)), y1 = static_cast<int>(std::ceil(std::max(ay, by) + width));
        const float dx = bx - ax, dy = by - ay, length2 = dx * dx + dy * dy;
        for (int y = y0; y <= y1; ++y)
            for (int x = x0; x <= x1; ++x) {
                const float px = x + 0.5f, py = y + 0.5f;
                const float t = length2 > 0 ? std::clamp(((px - ax) * dx + (py - ay) * dy) / length2, 0.0f, 1.0f) : 0.0f;
                const float distance = std::hypot(px - (ax + t * dx), py - (ay + t * dy));
                put(x, y, c, width * 0.5f + 0.5f - distance);
            }
    }
    void text(int x, int y, const std::string& s, Rgb c, int scale = 2) {
        std::vector<float> buffer(s.size() * 16 * 64);  // stb_easy_font: at most ~40 quads per character
        unsigned char color[4] = {0, 0, 0, 255};
        std::string copy = s;
        const int quads = stb_easy_font_print(0, 0, copy.data(), color, buffer.data(), static_cast<int>(buffer.size() * sizeof(float)));
        const float* v = buffer.data();
        for (int q = 0; q < quads; ++q, v += 16) {  // 4 vertices of x, y, z, colour
            const int qx0 = static_cast<int>(v[0]), qy0 = static_cast<int>(v[1]);
            const int qx1 = static_cast<int>(v[8]), qy1 = static_cast<int>(v[9]);
            rect(x + qx0 * scale, y + qy0 * scale, x + qx1 * scale, y + qy1 * scale, c);
        }
    }
    static int text_width(const std::string& s, int scale = 2) {
        std::string copy = s;
        return stb_easy_font_width(copy.data()) * scale;
    }
    image::FloatImage take() { return std::move(image_); }

private:
    image::FloatImage image_;
};

const Rgb kPalette[] = {{0.12f, 0.47f, 0.71f}, {1.0f, 0.50f, 0.05f}, {0.17f, 0.63f, 0.17f}, {0.84f, 0.15f, 0.16f},
                        {0.58f, 0.40f, 0.74f}, {0.55f, 0.34f, 0.29f}, {0.89f, 0.47f, 0.76f}, {0.5f, 0.5f, 0.5f},
                        {0.74f, 0.74f, 0.13f}, {0.09f, 0.75f, 0.81f}};

std::string number(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", v);
    return text;
}

// A "nice" axis maximum and tick step: 1, 2 or 5 times a power of ten.
std::pair<double, double> nice_axis(double max) {
    if (!(max > 0)) max = 1;
    const double raw = max / 5;
    const double power = std::pow(10.0, std::floor(std::log10(raw)));
    double step = power;
    for (double m : {1.0, 2.0, 5.0, 10.0})
        if (raw <= m * power) {
            step = m * power;
            break;
        }
    return {std::ceil(max / step) * step, step};
}

}  // namespace

image::FloatImage plot_spectra(const std::vector<spectral::NamedSpectrum>& spectra, const spectral::Observer& observer,
                               const PlotOptions& o) {
    Canvas canvas(o.width, o.height);
    const int left = 80, right = o.width - 200, top = 30, bottom = o.height - 90;
    double peak = 0;
    for (const auto& s : spectra)
        for (int nm = o.lower_nm; nm <= o.upper_nm; ++nm)
            peak = std::max(peak, o.normalise ? 1.0 : s.spectrum.at(nm));
    const auto axis = nice_axis(peak * 1.02);  // not a structured binding: lambdas below capture it (clang 14)
    const double y_max = axis.first, y_step = axis.second;
    const auto px = [&](double nm) { return left + (nm - o.lower_nm) / (o.upper_nm - o.lower_nm) * (right - left); };
    const auto py = [&](double v) { return bottom - v / y_max * (bottom - top); };
    const Rgb grid{0.88f, 0.88f, 0.88f}, ink{0.1f, 0.1f, 0.1f};

    for (double v = 0; v <= y_max + 1e-9; v += y_step) {
        canvas.line(left, static_cast<float>(py(v)), right, static_cast<float>(py(v)), grid, 1.0f);
        const std::string label = number(v);
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
        const Rgb color = kPalette[i % (sizeof kPalette / sizeof kPalette[0])];
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
