#include "core/text.hpp"
#include "image/image_file.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "core/error.hpp"

namespace fxview::image {
void write_image(const std::string& path, const FloatImage& image, Encoding png_encoding) {
    const std::string extension = lower_extension(path);
    if (extension == ".png") return write_png(path, image, png_encoding);
    if (extension == ".exr") return write_exr(path, image);
    if (extension == ".pfm") return write_pfm(path, image);
    throw UsageError(path + ": unsupported image type '" + extension + "' (expected .png, .exr or .pfm)");
}

FloatImage read_float_image(const std::string& path) {
    const std::string extension = lower_extension(path);
    if (extension == ".exr") return read_exr(path);
    if (extension == ".pfm") return read_pfm(path);
    throw UsageError(path + ": not a float image (expected .exr or .pfm)");
}

}  // namespace fxview::image
