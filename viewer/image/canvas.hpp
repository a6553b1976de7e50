// A small chart canvas: an 8-bit-looking RGBA float image with anti-aliased lines, rectangles and
// stb_easy_font text, drawn in sRGB-encoded colours (what the eye sees) and stored linear, so that
// the PNG writer's encoding gives back exactly these colours. Used by the spectrum and BRDF charts.
#pragma once
#include <string>
#include <utility>

#include "image/image.hpp"

namespace fxview::image {

struct Rgb {
    float r, g, b;
};

class Canvas {
public:
    Canvas(int width, int height);
    void put(int x, int y, Rgb c, float coverage);
    void rect(int x0, int y0, int x1, int y1, Rgb c);
    // Anti-aliased line of the given width: coverage from the distance to the segment.
    void line(float ax, float ay, float bx, float by, Rgb c, float width);
    void text(int x, int y, const std::string& s, Rgb c, int scale = 2);
    static int text_width(const std::string& s, int scale = 2);
    FloatImage take() { return std::move(image_); }
    int width() const { return image_.width; }

private:
    FloatImage image_;
};

// Distinguishable line colours (sRGB), for series 0, 1, ...: ten chosen ones, then hues a golden
// angle apart (never the same colour twice).
Rgb palette(size_t index);
// A number as a chart label (%g).
std::string chart_number(double v);
// A "nice" axis maximum and tick step for values up to `max`: 1, 2 or 5 times a power of ten.
std::pair<double, double> nice_axis(double max);

}  // namespace fxview::image
