#include "image/pixel_info.hpp"

#include <string>

#include "core/error.hpp"

namespace fxview::image {

PixelInfo inspect_pixel(const FloatImage& image, int x, int y, Encoding encoding) {
    if (x < 0 || y < 0 || x >= image.width || y >= image.height)
        throw UsageError("pixel " + std::to_string(x) + "," + std::to_string(y) + " lies outside the " +
                         std::to_string(image.width) + "x" + std::to_string(image.height) + " image");
    PixelInfo info;
    info.x = x;
    info.y = y;
    const float* value = image.pixel(x, y);
    for (int c = 0; c < 4; ++c) info.rgba[c] = c < image.channels ? value[c] : (c == 3 ? 1.0f : 0.0f);
    for (int c = 0; c < 3; ++c) info.rgba8[c] = to_8bit(info.rgba[c], encoding);
    info.rgba8[3] = to_8bit(info.rgba[3], Encoding::Linear);
    info.packed = info.rgba8[0] | (info.rgba8[1] << 8) | (info.rgba8[2] << 16) | (std::uint32_t(info.rgba8[3]) << 24);
    const glm::vec3 unmapped = glm::vec3(info.rgba[0], info.rgba[1], info.rgba[2]) * 2.0f - 1.0f;
    info.normal = glm::length(unmapped) > 0.0f ? glm::normalize(unmapped) : glm::vec3(0.0f);
    return info;
}

}  // namespace fxview::image
