// OpenEXR through tinyexr, 32-bit float channels so that a round trip is bit-exact.
#include <tinyexr.h>

#include <algorithm>
#include <cstdlib>
#include <memory>

#include "core/error.hpp"
#include "image/image_file.hpp"

namespace fxview::image {
namespace {

std::string take_error(const char* error) {
    std::string message = error ? error : "unknown error";
    if (error) FreeEXRErrorMessage(error);
    return message;
}

}  // namespace

void write_exr(const std::string& path, const FloatImage& image) {
    if (image.empty()) throw Error(path + ": empty image");
    if (image.channels != 1 && image.channels != 3 && image.channels != 4)
        throw Error(path + ": EXR needs 1, 3 or 4 channels");
    const char* error = nullptr;
    if (SaveEXR(image.data.data(), image.width, image.height, image.channels, /*save_as_fp16=*/0, path.c_str(),
                &error) != TINYEXR_SUCCESS)
        throw Error(path + ": cannot write EXR: " + take_error(error));
}

FloatImage read_exr(const std::string& path) {
    float* rgba = nullptr;
    int width = 0, height = 0;
    const char* error = nullptr;
    if (LoadEXR(&rgba, &width, &height, path.c_str(), &error) != TINYEXR_SUCCESS)
        throw Error(path + ": cannot read EXR: " + take_error(error));
    std::unique_ptr<float, decltype(&std::free)> owner(rgba, &std::free);
    FloatImage image(width, height, 4);
    std::copy_n(rgba, image.data.size(), image.data.begin());
    return image;
}

}  // namespace fxview::image
