// Image files, chosen by extension: PNG (8-bit RGBA, sRGB-encoded unless told otherwise),
// OpenEXR (32-bit float RGBA through tinyexr) and PFM (32-bit float; RGBA as the "PF4" variant).
#pragma once
#include <string>

#include "image/color_encoding.hpp"
#include "image/image.hpp"

namespace fxview::image {

// Throws UsageError for an unsupported extension, Error when the file cannot be written.
void write_image(const std::string& path, const FloatImage& image, Encoding png_encoding = Encoding::Srgb);

// Float formats only (.exr, .pfm); the result has the file's channels (EXR: always 4).
FloatImage read_float_image(const std::string& path);

void write_png(const std::string& path, const FloatImage& image, Encoding encoding);
void write_exr(const std::string& path, const FloatImage& image);
FloatImage read_exr(const std::string& path);
void write_pfm(const std::string& path, const FloatImage& image);
FloatImage read_pfm(const std::string& path);

}  // namespace fxview::image
