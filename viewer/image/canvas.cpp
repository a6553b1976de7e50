#include "image/canvas.hpp"

#include <stb/stb_easy_font.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "image/color_encoding.hpp"

namespace fxview::image {

Canvas::Canvas(int width, int height) : image_(width, height, 4) {
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) put(x, y, {1, 1, 1}, 1.0f);
}

void Canvas::put(int x, int y, Rgb c, float coverage) {
    if (x < 0 || y < 0 || x >= image_.width || y >= image_.height || coverage <= 0) return;
    float* p = image_.pixel(x, y);
    const float a = std::min(coverage, 1.0f);
    const float encoded[3] = {c.r, c.g, c.b};
    for (int k = 0; k < 3; ++k) {
        const float current = srgb_encode(p[k]);
        p[k] = srgb_decode(current + (encoded[k] - current) * a);
    }
    p[3] = 1.0f;
}

void Canvas::rect(int x0, int y0, int x1, int y1, Rgb c) {
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) put(x, y, c, 1.0f);
}

void Canvas::line(float ax, float ay, float bx, float by, Rgb c, float width) {
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

void Canvas::text(int x, int y, const std::string& s, Rgb c, int scale) {
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

int Canvas::text_width(const std::string& s, int scale) {
    std::string copy = s;
    return stb_easy_font_width(copy.data()) * scale;
}

Rgb palette(size_t index) {
    static const Rgb colours[] = {{0.12f, 0.47f, 0.71f}, {1.0f, 0.50f, 0.05f}, {0.17f, 0.63f, 0.17f}, {0.84f, 0.15f, 0.16f},
                                  {0.58f, 0.40f, 0.74f}, {0.55f, 0.34f, 0.29f}, {0.89f, 0.47f, 0.76f}, {0.5f, 0.5f, 0.5f},
                                  {0.74f, 0.74f, 0.13f}, {0.09f, 0.75f, 0.81f}};
    constexpr size_t count = sizeof colours / sizeof colours[0];
    if (index < count) return colours[index];
    // Beyond the ten: hues a golden angle apart at two lightnesses, so that no two curves share a colour.
    const float hue = std::fmod(0.1f + 0.618034f * static_cast<float>(index), 1.0f) * 6.0f, value = index % 2 ? 0.62f : 0.85f;
    const float f = hue - std::floor(hue), p = value * 0.3f, q = value * (1.0f - 0.7f * f), t = value * (1.0f - 0.7f * (1.0f - f));
    switch (static_cast<int>(hue) % 6) {
        case 0: return {value, t, p};
        case 1: return {q, value, p};
        case 2: return {p, value, t};
        case 3: return {p, q, value};
        case 4: return {t, p, value};
        default: return {value, p, q};
    }
}

std::string chart_number(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", v);
    return text;
}

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

}  // namespace fxview::image
