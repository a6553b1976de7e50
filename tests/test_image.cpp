// Colour encoding against the sRGB standard's numbers, pixel-pick decoding, and bit-exact float
// image round trips through EXR and PFM (with the values that break lossy paths: NaN, inf, denormals).
#include <doctest/doctest.h>

#include "test_support.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>

#include "core/error.hpp"
#include "image/canvas.hpp"
#include "image/image_file.hpp"
#include "image/pixel_info.hpp"

using fxview::test::temp_path;

using namespace fxview::image;

namespace {

FloatImage awkward_image(int width, int height, int channels) {
    FloatImage image(width, height, channels);
    for (size_t i = 0; i < image.data.size(); ++i) image.data[i] = std::sin(0.37f * static_cast<float>(i)) * 1e3f / (1.0f + i);
    image.data[0] = std::numeric_limits<float>::denorm_min();
    image.data[1] = -0.0f;
    image.data[2] = std::numeric_limits<float>::max();
    image.data[3] = std::numeric_limits<float>::infinity();
    return image;
}

bool bit_identical(const FloatImage& a, const FloatImage& b) {
    return a.width == b.width && a.height == b.height && a.channels == b.channels &&
           std::memcmp(a.data.data(), b.data.data(), a.data.size() * sizeof(float)) == 0;
}

}  // namespace

TEST_CASE("sRGB encoding follows IEC 61966-2-1") {
    // Published reference points of the sRGB curve: linear 0.5 -> 0.735357, 0.18 -> 0.461356;
    // the linear segment ends at 0.0031308 -> 0.04045. Float pow is good to ~1e-6.
    CHECK(srgb_encode(0.5f) == doctest::Approx(0.735357f).epsilon(2e-6));
    CHECK(srgb_encode(0.18f) == doctest::Approx(0.461356f).epsilon(2e-6));
    CHECK(srgb_encode(0.0031308f) == doctest::Approx(0.04045f).epsilon(1e-4));
    CHECK(srgb_encode(1.0f) == doctest::Approx(1.0f));
    CHECK(srgb_encode(2.0f) == 1.0f);   // clipped
    CHECK(srgb_encode(-1.0f) == 0.0f);  // clipped
    CHECK(srgb_decode(srgb_encode(0.3f)) == doctest::Approx(0.3f).epsilon(1e-5));
    CHECK(to_8bit(0.5f, Encoding::Srgb) == 188);    // round(0.735357 * 255) = 187.5 -> 188
    CHECK(to_8bit(0.5f, Encoding::Linear) == 128);  // round(127.5) = 128
    CHECK(to_8bit(std::nanf(""), Encoding::Linear) == 0);
}

TEST_CASE("pixel info: 8-bit value, packed integer and decoded normal") {
    FloatImage image(2, 1, 4);
    // A normal (0, 0.6, 0.8) mapped by eq. 55 to (0.5, 0.8, 0.9).
    const float mapped[4] = {0.5f, 0.8f, 0.9f, 1.0f};
    std::copy_n(mapped, 4, image.pixel(1, 0));
    const PixelInfo info = inspect_pixel(image, 1, 0, Encoding::Linear);
    CHECK(info.rgba8[0] == 128);
    CHECK(info.rgba8[1] == 204);
    CHECK(info.rgba8[2] == 230);
    CHECK(info.rgba8[3] == 255);
    CHECK(info.packed == (128u | 204u << 8 | 230u << 16 | 255u << 24));
    CHECK(info.normal.x == doctest::Approx(0.0f));
    CHECK(info.normal.y == doctest::Approx(0.6f));
    CHECK(info.normal.z == doctest::Approx(0.8f));
    CHECK_THROWS_AS(inspect_pixel(image, 2, 0, Encoding::Srgb), fxview::UsageError);
    CHECK_THROWS_AS(inspect_pixel(image, 0, -1, Encoding::Srgb), fxview::UsageError);
}

TEST_CASE("PFM round trips are bit-exact for 1, 3 and 4 channels") {
    for (int channels : {1, 3, 4}) {
        CAPTURE(channels);
        const FloatImage original = awkward_image(7, 5, channels);
        const std::string path = temp_path("roundtrip" + std::to_string(channels) + ".pfm");
        write_pfm(path, original);
        CHECK(bit_identical(read_pfm(path), original));
    }
    // Rows are stored bottom-up: the first float in the file's data is the bottom-left pixel.
    FloatImage marked(2, 2, 1);
    marked.data = {1, 2, 3, 4};  // top row 1 2, bottom row 3 4
    const std::string path = temp_path("order.pfm");
    write_pfm(path, marked);
    std::ifstream file(path, std::ios::binary);
    std::string magic, size, scale;
    file >> magic;
    std::getline(file, size);
    std::getline(file, size);
    std::getline(file, scale);
    float first = 0;
    file.read(reinterpret_cast<char*>(&first), 4);
    CHECK(magic == "Pf");
    CHECK(first == 3.0f);
}

TEST_CASE("broken PFM files are rejected with the file name") {
    const std::string truncated = temp_path("truncated.pfm");
    {
        std::ofstream file(truncated, std::ios::binary);
        file << "PF\n4 4\n-1.0\n";
        const float some[5] = {1, 2, 3, 4, 5};
        file.write(reinterpret_cast<const char*>(some), sizeof some);
    }
    CHECK_THROWS_WITH_AS(read_pfm(truncated), doctest::Contains("truncated.pfm: PFM data ends early"), fxview::Error);
    const std::string garbage = temp_path("garbage.pfm");
    { std::ofstream(garbage) << "P6\n4 4\n255\n"; }
    CHECK_THROWS_WITH_AS(read_pfm(garbage), doctest::Contains("not a PFM file"), fxview::Error);
    CHECK_THROWS_AS(read_pfm(temp_path("does-not-exist.pfm")), fxview::Error);
}

TEST_CASE("EXR round trips are bit-exact in 32-bit float RGBA") {
    for (const auto& [width, height] : {std::pair{5, 3}, std::pair{40, 33}}) {  // uncompressed and ZIP paths
        const FloatImage original = awkward_image(width, height, 4);
        const std::string path = temp_path("roundtrip" + std::to_string(width) + ".exr");
        write_exr(path, original);
        CHECK(bit_identical(read_exr(path), original));
    }
    CHECK_THROWS_AS(read_exr(temp_path("does-not-exist.exr")), fxview::Error);
}

TEST_CASE("PNG writing and extension dispatch") {
    FloatImage image(3, 2, 4);
    const std::string png = temp_path("small.png");
    write_image(png, image);
    CHECK(std::filesystem::file_size(png) > 0);
    CHECK_THROWS_AS(write_image(temp_path("x.bmp"), image), fxview::UsageError);
    CHECK_THROWS_AS(read_float_image(png), fxview::UsageError);
    CHECK_THROWS_AS(write_image("/nonexistent-dir/x.png", image), fxview::Error);
}

TEST_CASE("chart colours: no two of the first 40 series share a colour") {
    // Issue 28: an 11th curve reused the first colour. Among 20 curves every pair differs by 0.08 in
    // some sRGB channel (clearly visible on a line); among 40, by 0.03 at least (no repeat).
    for (size_t i = 0; i < 40; ++i)
        for (size_t j = i + 1; j < 40; ++j) {
            const fxview::image::Rgb a = fxview::image::palette(i), b = fxview::image::palette(j);
            CAPTURE(i);
            CAPTURE(j);
            CHECK(std::max({std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b)}) > (j < 20 ? 0.08f : 0.03f));
        }
}
