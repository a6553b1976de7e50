#include "image/color_encoding.hpp"

#include <algorithm>
#include <cmath>

namespace fxview::image {

float srgb_encode(float linear) {
    const float x = std::clamp(linear, 0.0f, 1.0f);
    if (x >= 1.0f) return 1.0f;  // the float curve misses 1 by an ulp
    return x <= 0.0031308f ? 12.92f * x : 1.055f * std::pow(x, 1.0f / 2.4f) - 0.055f;
}

float srgb_decode(float encoded) {
    const float x = std::clamp(encoded, 0.0f, 1.0f);
    return x <= 0.04045f ? x / 12.92f : std::pow((x + 0.055f) / 1.055f, 2.4f);
}

std::uint8_t to_8bit(float value, Encoding encoding) {
    const float encoded = encoding == Encoding::Srgb ? srgb_encode(value) : std::clamp(value, 0.0f, 1.0f);
    if (std::isnan(encoded)) return 0;
    return static_cast<std::uint8_t>(std::lround(encoded * 255.0f));
}

}  // namespace fxview::image
