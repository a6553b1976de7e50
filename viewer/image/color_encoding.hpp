// Turning linear float colour into the 8-bit values a screen or PNG shows.
#pragma once
#include <cstdint>

namespace fxview::image {

enum class Encoding {
    Srgb,    // IEC 61966-2-1 transfer function (default: what a monitor expects)
    Linear,  // legacy: linear value scaled to 8 bits, as the original ShaderViewer wrote it
};

float srgb_encode(float linear);  // input clamped to [0,1]
float srgb_decode(float encoded);
std::uint8_t to_8bit(float value, Encoding encoding);  // rounds to nearest code value; alpha uses Linear

}  // namespace fxview::image
