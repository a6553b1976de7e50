// A float image in memory: RGBA (or fewer channels), rows stored top to bottom, x to the right,
// the layout every file format and pixel coordinate of fxview uses.
#pragma once
#include <cstddef>
#include <vector>

namespace fxview::image {

struct FloatImage {
    int width = 0;
    int height = 0;
    int channels = 4;
    std::vector<float> data;  // width * height * channels, top row first

    FloatImage() = default;
    FloatImage(int w, int h, int c = 4)
        : width(w), height(h), channels(c), data(static_cast<size_t>(w) * h * c, 0.0f) {}

    float* pixel(int x, int y) { return data.data() + (static_cast<size_t>(y) * width + x) * channels; }
    const float* pixel(int x, int y) const {
        return data.data() + (static_cast<size_t>(y) * width + x) * channels;
    }
    bool empty() const { return data.empty(); }
};

}  // namespace fxview::image
