// PNG through stb_image_write (Debian's libstb carries the implementation).
#include <stb/stb_image_write.h>

#include <vector>

#include "core/error.hpp"
#include "image/image_file.hpp"

namespace fxview::image {

void write_png(const std::string& path, const FloatImage& image, Encoding encoding) {
    if (image.empty()) throw Error(path + ": empty image");
    std::vector<unsigned char> bytes(static_cast<size_t>(image.width) * image.height * 4);
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const float* in = image.pixel(x, y);
            unsigned char* out = &bytes[(static_cast<size_t>(y) * image.width + x) * 4];
            const int c = image.channels;
            for (int k = 0; k < 3; ++k) out[k] = to_8bit(in[std::min(k, c - 1)], encoding);
            out[3] = c == 4 ? to_8bit(in[3], Encoding::Linear) : 255;  // alpha is never gamma-encoded
        }
    if (!stbi_write_png(path.c_str(), image.width, image.height, 4, bytes.data(), image.width * 4))
        throw Error(path + ": cannot write PNG");
}

}  // namespace fxview::image
