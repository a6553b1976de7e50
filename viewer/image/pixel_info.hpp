// What a pixel pick reports (seed 002 ch. 4.1): the float value, the 8-bit colour on screen, its
// packed integer and the value decoded as a normal (inverse of eq. 55).
#pragma once
#include <array>
#include <cstdint>

#include <glm/glm.hpp>

#include "image/color_encoding.hpp"
#include "image/image.hpp"

namespace fxview::image {

struct PixelInfo {
    int x = 0, y = 0;                     // pixel coordinates, origin top left
    std::array<float, 4> rgba{};          // exactly what the shader wrote
    std::array<std::uint8_t, 4> rgba8{};  // as displayed / written to PNG
    std::uint32_t packed = 0;             // R + G*2^8 + B*2^16 + A*2^24: the RGBA bytes as one little-endian word
    glm::vec3 normal{0.0f};               // normalize(2*rgb - 1); zero for a zero vector
};

PixelInfo inspect_pixel(const FloatImage& image, int x, int y, Encoding encoding);  // throws Error off the image

}  // namespace fxview::image
