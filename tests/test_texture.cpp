// Texture files written from code in each test, loaded, and checked texel by texel; then uploaded
// to GL (EGL backend) and read back. Also FTXT rejection, cube crosses, DDS variants and errors.
#include <doctest/doctest.h>

#include "test_support.hpp"

#include <stb/stb_image_write.h>

#include <cstring>
#include <filesystem>
#include <fstream>

#include <glm/gtc/packing.hpp>

#include "context/context.hpp"
#include "core/error.hpp"
#include "gl/texture_upload.hpp"
#include "texture/placeholder.hpp"
#include "image/image_file.hpp"
#include "texture/texture_file.hpp"

using namespace fxview;
using fxview::test::shared_context;
using fxview::test::temp_path;
using namespace fxview::texture;

namespace {

// 3x2 RGBA8 test pattern, top row first: every texel different in every channel.
const std::uint8_t kPattern[2][3][4] = {{{255, 0, 0, 255}, {0, 255, 0, 128}, {0, 0, 255, 0}},
                                        {{10, 20, 30, 40}, {50, 60, 70, 80}, {90, 100, 110, 120}}};

void check_pattern(const TextureData& t, int tolerance) {
    REQUIRE(t.width() == 3);
    REQUIRE(t.height() == 2);
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 3; ++x) {
            float rgba[4];
            read_texel(t, 0, 0, x, y, rgba);
            for (int c = 0; c < 4; ++c) {
                CAPTURE(x);
                CAPTURE(y);
                CAPTURE(c);
                CHECK(std::abs(rgba[c] * 255.0f - kPattern[y][x][c]) <= tolerance + 1e-3f);
            }
        }
}

struct DdsHeader {
    std::uint32_t words[32] = {};  // "DDS " + 124-byte header
    DdsHeader(int width, int height, int mips) {
        std::memcpy(&words[0], "DDS ", 4);
        words[1] = 124;
        words[2] = 0x1007 | (mips > 1 ? 0x20000 : 0);
        words[3] = static_cast<std::uint32_t>(height);
        words[4] = static_cast<std::uint32_t>(width);
        words[7] = static_cast<std::uint32_t>(mips);
        words[19] = 32;  // pixel format size
    }
};

void write_file(const std::string& path, const std::vector<std::uint8_t>& bytes) {
    std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
}

std::vector<std::uint8_t> bytes_of(const DdsHeader& header) {
    std::vector<std::uint8_t> bytes(128);
    std::memcpy(bytes.data(), header.words, 128);
    return bytes;
}

template <typename T>
void append(std::vector<std::uint8_t>& bytes, const T& value) {
    const auto* p = reinterpret_cast<const std::uint8_t*>(&value);
    bytes.insert(bytes.end(), p, p + sizeof(T));
}

}  // namespace

TEST_CASE("PNG, BMP and TGA load bit-exact; JPEG within its loss") {
    const std::string png = temp_path("pattern.png"), bmp = temp_path("pattern.bmp"), tga = temp_path("pattern.tga");
    REQUIRE(stbi_write_png(png.c_str(), 3, 2, 4, kPattern, 12));
    REQUIRE(stbi_write_tga(tga.c_str(), 3, 2, 4, kPattern));
    REQUIRE(stbi_write_bmp(bmp.c_str(), 3, 2, 4, kPattern));
    check_pattern(load_texture_file(png), 0);
    check_pattern(load_texture_file(tga), 0);
    // BMP through stb keeps no alpha channel: check colour only.
    const TextureData b = load_texture_file(bmp);
    float rgba[4];
    read_texel(b, 0, 0, 2, 1, rgba);
    CHECK(rgba[0] * 255.0f == doctest::Approx(90.0f));
    CHECK(rgba[2] * 255.0f == doctest::Approx(110.0f));
    // JPEG of a flat colour: DCT of a constant block is exact apart from rounding (<= 2 codes).
    std::vector<std::uint8_t> flat(16 * 16 * 3);
    for (size_t i = 0; i < flat.size(); i += 3) flat[i] = 200, flat[i + 1] = 100, flat[i + 2] = 50;
    const std::string jpg = temp_path("flat.jpg");
    REQUIRE(stbi_write_jpg(jpg.c_str(), 16, 16, 3, flat.data(), 100));
    read_texel(load_texture_file(jpg), 0, 0, 7, 7, rgba);
    CHECK(std::abs(rgba[0] * 255.0f - 200.0f) <= 2.0f);
    CHECK(std::abs(rgba[1] * 255.0f - 100.0f) <= 2.0f);
    CHECK(std::abs(rgba[2] * 255.0f - 50.0f) <= 2.0f);
}

TEST_CASE("HDR and EXR load as 32-bit float") {
    // RGBE stores a shared exponent and 8-bit mantissas, decoded as Radiance's colr_color() does, in
    // the middle of the mantissa's step: (4, 2, 1) is stored as mantissas (128, 64, 32) at 2^-5 and
    // reads (128.5, 64.5, 32.5) / 32, exactly in float.
    const float hdr_pixels[2 * 1 * 3] = {1.0f, 0.5f, 0.25f, 4.0f, 2.0f, 1.0f};
    const std::string hdr = temp_path("pixels.hdr");
    REQUIRE(stbi_write_hdr(hdr.c_str(), 2, 1, 3, hdr_pixels));
    const TextureData h = load_texture_file(hdr);
    CHECK(h.format == PixelFormat::RGBA32F);
    float rgba[4];
    read_texel(h, 0, 0, 1, 0, rgba);
    CHECK(rgba[0] == 128.5f / 32);
    CHECK(rgba[1] == 64.5f / 32);
    CHECK(rgba[2] == 32.5f / 32);
    image::FloatImage exr_image(2, 2, 4);
    for (size_t i = 0; i < exr_image.data.size(); ++i) exr_image.data[i] = 0.1f * static_cast<float>(i) - 0.3f;
    const std::string exr = temp_path("texture.exr");
    image::write_exr(exr, exr_image);
    const TextureData e = load_texture_file(exr);
    read_texel(e, 0, 0, 1, 1, rgba);
    CHECK(std::memcmp(rgba, exr_image.pixel(1, 1), 16) == 0);
}

TEST_CASE("FTXT: size line, R;G;B;A per texel, incomplete data rejected and discarded") {
    const std::string good = temp_path("good.ftxt");
    std::ofstream(good) << "# a comment\n2 2\n0.1;0.2;0.3;0.4\n1e-3;2;-3;4.5\n\n0;0;0;1\n0.5;0.25;0.125;1\n";
    const TextureData t = load_texture_file(good);
    CHECK(t.format == PixelFormat::RGBA32F);
    float rgba[4];
    read_texel(t, 0, 0, 1, 0, rgba);
    CHECK(rgba[0] == 1e-3f);
    CHECK(rgba[2] == -3.0f);
    read_texel(t, 0, 0, 1, 1, rgba);
    CHECK(rgba[2] == 0.125f);
    const std::string short_file = temp_path("short.ftxt");
    std::ofstream(short_file) << "2 2\n1;1;1;1\n1;1;1;1\n1;1;1;1\n";
    CHECK_THROWS_WITH_AS(load_texture_file(short_file), doctest::Contains("short.ftxt:4: FTXT data ends after 3 of 4 texels"), Error);
    const std::string bad_line = temp_path("badline.ftxt");
    std::ofstream(bad_line) << "1 2\n1;1;1;1\n1;1;1\n";
    CHECK_THROWS_WITH_AS(load_texture_file(bad_line), doctest::Contains("badline.ftxt:3: a texel line needs four values"), Error);
    const std::string too_many = temp_path("toomany.ftxt");
    std::ofstream(too_many) << "1\n1;1;1;1\n2;2;2;2\n";
    CHECK_THROWS_WITH_AS(load_texture_file(too_many), doctest::Contains("toomany.ftxt:3: more texel lines"), Error);
    const std::string not_number = temp_path("nan.ftxt");
    std::ofstream(not_number) << "1 1\n1;x;1;1\n";
    CHECK_THROWS_WITH_AS(load_texture_file(not_number), doctest::Contains("nan.ftxt:2: 'x' is not a finite number"), Error);
    const std::string bad_size = temp_path("badsize.ftxt");
    std::ofstream(bad_size) << "0 4\n";
    CHECK_THROWS_WITH_AS(load_texture_file(bad_size), doctest::Contains("badsize.ftxt:1: bad FTXT size"), Error);
}

TEST_CASE("cube crosses split into the six faces in both layouts") {
    for (const bool vertical : {true, false}) {
        CAPTURE(vertical);
        const int size = 4, columns = vertical ? 3 : 4, rows = vertical ? 4 : 3;
        TextureData cross;
        cross.source = "cross";
        cross.format = PixelFormat::RGBA8;
        Level level{columns * size, rows * size, std::vector<std::uint8_t>(static_cast<size_t>(columns * size * rows * size * 4), 0)};
        // Each cell's red = 10 * cell index + 1; green marks the cell's top-left texel with 255.
        for (int y = 0; y < rows * size; ++y)
            for (int x = 0; x < columns * size; ++x) {
                std::uint8_t* p = &level.bytes[(static_cast<size_t>(y) * columns * size + x) * 4];
                p[0] = static_cast<std::uint8_t>(10 * ((y / size) * columns + x / size) + 1);
                p[1] = (x % size == 0 && y % size == 0) ? 255 : 0;
                p[3] = 255;
            }
        cross.faces = {{level}};
        const TextureData cube = split_cube_cross(cross);
        REQUIRE(cube.type == TextureType::Cube);
        REQUIRE(cube.faces.size() == 6);
        // Cells (column,row) of +X -X +Y -Y +Z -Z.
        const int vertical_cells[6][2] = {{2, 1}, {0, 1}, {1, 0}, {1, 2}, {1, 1}, {1, 3}};
        const int horizontal_cells[6][2] = {{2, 1}, {0, 1}, {1, 0}, {1, 2}, {1, 1}, {3, 1}};
        for (int face = 0; face < 6; ++face) {
            CAPTURE(face);
            const auto& cell = vertical ? vertical_cells[face] : horizontal_cells[face];
            const auto& bytes = cube.faces[face][0].bytes;
            CHECK(bytes[0] == 10 * (cell[1] * columns + cell[0]) + 1);
            // The marker stays top-left, except -Z of the vertical cross, stored upside down.
            const bool rotated = vertical && face == 5;
            const size_t marker = rotated ? (static_cast<size_t>(size * size) - 1) * 4 : 0;
            CHECK(bytes[marker + 1] == 255);
        }
    }
    TextureData uneven;
    uneven.source = "uneven.png";
    uneven.faces = {{Level{10, 12, std::vector<std::uint8_t>(10 * 12 * 4)}}};
    CHECK_THROWS_WITH_AS(split_cube_cross(uneven), doctest::Contains("vertical cube cross must be 3x4 equal squares"), Error);
}

TEST_CASE("1D textures come from images one pixel high") {
    TextureData row;
    row.source = "row.png";
    row.faces = {{Level{8, 1, std::vector<std::uint8_t>(32)}}};
    CHECK(as_1d(row).type == TextureType::Tex1D);
    row.faces = {{Level{8, 2, std::vector<std::uint8_t>(64)}}};
    CHECK_THROWS_WITH_AS(as_1d(row), doctest::Contains("one pixel high"), Error);
}

TEST_CASE("3D textures: slices stacked in an image, and DDS volumes; both survive the GL round trip") {
    const std::string stacked = temp_path("stacked.ftxt");  // 2 wide, 2 slices of 2 rows: value = 10*slice + 2*row + col
    std::ofstream(stacked) << "2 4\n0;0;0;1\n1;0;0;1\n2;0;0;1\n3;0;0;1\n10;0;0;1\n11;0;0;1\n12;0;0;1\n13;0;0;1\n";
    const TextureData volume = as_3d(load_texture_file(stacked), 2);
    CHECK(volume.type == TextureType::Tex3D);
    CHECK(volume.height() == 2);
    CHECK(volume.depth() == 2);
    float rgba[4];
    read_texel(volume, 0, 0, 1, 0, rgba, 1);
    CHECK(rgba[0] == 11.0f);
    CHECK_THROWS_WITH_AS(as_3d(load_texture_file(stacked), 3), doctest::Contains("does not split into 3 equal slices"), Error);

    DdsHeader header(2, 1, 1);
    header.words[6] = 3;  // depth
    header.words[20] = 0x41;
    header.words[22] = 32;
    header.words[23] = 0xFF, header.words[24] = 0xFF00, header.words[25] = 0xFF0000, header.words[26] = 0xFF000000;
    header.words[28] = 0x200000;  // DDSCAPS2_VOLUME
    auto bytes = bytes_of(header);
    for (std::uint8_t texel = 0; texel < 6; ++texel)
        for (std::uint8_t v : {std::uint8_t(texel * 40), std::uint8_t(0), std::uint8_t(0), std::uint8_t(255)}) bytes.push_back(v);
    const std::string path = temp_path("volume.dds");
    write_file(path, bytes);
    const TextureData dds = load_texture_file(path);
    CHECK(dds.type == TextureType::Tex3D);
    CHECK(dds.depth() == 3);
    read_texel(dds, 0, 0, 1, 0, rgba, 2);
    CHECK(rgba[0] * 255.0f == doctest::Approx(200.0f));

    shared_context();
    for (const TextureData* data : {&volume, &dds}) {
        const gl::Texture texture = gl::upload_texture(*data, {false, false});
        const auto texels = gl::download_texture(texture.get(), TextureType::Tex3D, 0, 0, data->width(), data->height(), data->depth());
        for (int z = 0; z < data->depth(); ++z)
            for (int y = 0; y < data->height(); ++y)
                for (int x = 0; x < data->width(); ++x) {
                    read_texel(*data, 0, 0, x, y, rgba, z);
                    const float got = texels[((static_cast<size_t>(z) * data->height() + y) * data->width() + x) * 4];
                    CHECK(std::abs(got - rgba[0]) <= 1e-6f);  // float exact; unorm8 within an ulp (see below)
                }
    }
}

TEST_CASE("DDS: RGBA8 (BGRA order) with mips, RGBA16F, RGBA32F via DX10, BC1, cube; broken files rejected") {
    // BGRA8, 2x2 with a 1x1 mip.
    DdsHeader header(2, 2, 2);
    header.words[20] = 0x41;  // DDPF_RGB | DDPF_ALPHAPIXELS
    header.words[22] = 32;
    header.words[23] = 0xFF0000, header.words[24] = 0xFF00, header.words[25] = 0xFF, header.words[26] = 0xFF000000;
    auto bytes = bytes_of(header);
    for (std::uint8_t v : {30, 20, 10, 40, 0, 0, 255, 255, 0, 255, 0, 255, 255, 0, 0, 255}) bytes.push_back(v);  // level 0
    for (std::uint8_t v : {7, 8, 9, 10}) bytes.push_back(v);                                                       // level 1
    const std::string bgra = temp_path("bgra.dds");
    write_file(bgra, bytes);
    const TextureData t = load_texture_file(bgra);
    CHECK(t.format == PixelFormat::RGBA8);
    CHECK(t.levels() == 2);
    CHECK(t.faces[0][0].bytes[0] == 10);  // red, swapped from BGRA
    CHECK(t.faces[0][0].bytes[2] == 30);
    CHECK(t.faces[0][1].bytes[0] == 9);

    // RGBA16F through the legacy D3DFMT code 113.
    DdsHeader half_header(1, 1, 1);
    half_header.words[20] = 0x4;
    half_header.words[21] = 113;
    auto half_bytes = bytes_of(half_header);
    for (float v : {0.5f, -2.0f, 1024.0f, 1.0f}) append(half_bytes, glm::packHalf1x16(v));
    const std::string half_path = temp_path("half.dds");
    write_file(half_path, half_bytes);
    float rgba[4];
    read_texel(load_texture_file(half_path), 0, 0, 0, 0, rgba);
    CHECK(rgba[0] == 0.5f);
    CHECK(rgba[1] == -2.0f);
    CHECK(rgba[2] == 1024.0f);

    // RGBA32F through a DX10 header (DXGI 2).
    DdsHeader dx10_header(1, 1, 1);
    dx10_header.words[20] = 0x4;
    std::memcpy(&dx10_header.words[21], "DX10", 4);
    auto dx10 = bytes_of(dx10_header);
    for (std::uint32_t w : {2u, 3u, 0u, 1u, 0u}) append(dx10, w);
    for (float v : {0.1f, 0.2f, 0.3f, 0.4f}) append(dx10, v);
    const std::string dx10_path = temp_path("float.dds");
    write_file(dx10_path, dx10);
    read_texel(load_texture_file(dx10_path), 0, 0, 0, 0, rgba);
    CHECK(rgba[1] == 0.2f);

    // BC1 (DXT1), one 4x4 block: endpoints red (0xF800) and blue (0x001F); row 1 uses index 1 (blue).
    DdsHeader bc1_header(4, 4, 1);
    bc1_header.words[20] = 0x4;
    std::memcpy(&bc1_header.words[21], "DXT1", 4);
    auto bc1 = bytes_of(bc1_header);
    for (std::uint8_t v : {0x00, 0xF8, 0x1F, 0x00, 0x00, 0x55, 0x00, 0x00}) bc1.push_back(v);
    const std::string bc1_path = temp_path("bc1.dds");
    write_file(bc1_path, bc1);
    const TextureData compressed = load_texture_file(bc1_path);
    CHECK(compressed.format == PixelFormat::BC1);

    // Cube map, 1x1 RGBA8 faces with red = face index.
    DdsHeader cube_header(1, 1, 1);
    cube_header.words[20] = 0x41;
    cube_header.words[22] = 32;
    cube_header.words[23] = 0xFF, cube_header.words[24] = 0xFF00, cube_header.words[25] = 0xFF0000, cube_header.words[26] = 0xFF000000;
    cube_header.words[28] = 0x200 | 0xFC00;
    auto cube = bytes_of(cube_header);
    for (std::uint8_t face = 0; face < 6; ++face)
        for (std::uint8_t v : {face, std::uint8_t(0), std::uint8_t(0), std::uint8_t(255)}) cube.push_back(v);
    const std::string cube_path = temp_path("cube.dds");
    write_file(cube_path, cube);
    const TextureData c = load_texture_file(cube_path);
    CHECK(c.type == TextureType::Cube);
    CHECK(c.faces[5][0].bytes[0] == 5);

    // Truncated data and garbage.
    bytes.resize(bytes.size() - 3);
    write_file(bgra, bytes);
    CHECK_THROWS_WITH_AS(load_texture_file(bgra), doctest::Contains("DDS data ends early"), Error);
    const std::string garbage = temp_path("garbage.dds");
    write_file(garbage, {1, 2, 3});
    CHECK_THROWS_WITH_AS(load_texture_file(garbage), doctest::Contains("not a DDS file"), Error);

    SUBCASE("uploaded to GL and read back texel by texel") {
        shared_context();
        const auto check_gl = [](const TextureData& data, bool mips) {
            const gl::Texture texture = gl::upload_texture(data, {false, mips});
            for (int face = 0; face < static_cast<int>(data.faces.size()); ++face)
                for (int level = 0; level < data.levels(); ++level) {
                    const auto& l = data.faces[face][level];
                    const auto texels = gl::download_texture(texture.get(), data.type, face, level, l.width, l.height);
                    for (int y = 0; y < l.height; ++y)
                        for (int x = 0; x < l.width; ++x) {
                            float expected[4];
                            read_texel(data, face, level, x, y, expected);
                            // Float data must come back bit-exact; unorm8 may differ by an ulp (GL
                            // may compute c * (1/255) where we divide by 255), far below one code (0.0039).
                            const float tolerance = data.format == PixelFormat::RGBA8 ? 1e-6f : 0.0f;
                            for (int ch = 0; ch < 4; ++ch)
                                CHECK(std::abs(texels[(static_cast<size_t>(y) * l.width + x) * 4 + ch] - expected[ch]) <= tolerance);
                        }
                }
        };
        check_gl(load_texture_file(half_path), false);
        check_gl(load_texture_file(dx10_path), false);
        check_gl(load_texture_file(cube_path), false);
        check_gl(load_texture_file(temp_path("good.ftxt")), false);
        check_gl(load_texture_file(temp_path("pattern.png")), false);
        // BC1 decodes on readback: row 1 blue, the other rows red (rows kept top-down through the flip).
        const gl::Texture bc = gl::upload_texture(compressed, {false, false});
        const auto texels = gl::download_texture(bc.get(), TextureType::Tex2D, 0, 0, 4, 4);
        CHECK(glGetError() == GL_NO_ERROR);
        CHECK(texels[0] == 1.0f);                 // (0,0) red
        CHECK(texels[(1 * 4 + 2) * 4 + 2] == 1.0f);  // (2,1) blue
        CHECK(texels[(1 * 4 + 2) * 4 + 0] == 0.0f);
        CHECK(texels[(3 * 4 + 3) * 4 + 0] == 1.0f);  // (3,3) red
    }
}

#include "reference/cpu_sampler.hpp"

TEST_CASE("CPU sampler: GL's nearest and linear filtering and wrap modes, checked by hand and against the GPU") {
    // A 4x1 float texture 0, 1, 2, 3 (left to right).
    TextureData row;
    row.format = PixelFormat::RGBA32F;
    row.source = "row";
    row.faces = {{Level{4, 1, std::vector<std::uint8_t>(64)}}};
    for (int i = 0; i < 4; ++i) {
        const float v[4] = {static_cast<float>(i), 0, 0, 1};
        std::memcpy(&row.faces[0][0].bytes[static_cast<size_t>(i) * 16], v, 16);
    }
    effect::SamplerState s;
    s.min_filter = s.mag_filter = GL_NEAREST;
    s.wrap_s = GL_REPEAT;
    CHECK(reference::sample_2d(row, s, false, {0.30, 0.5}).r == 1.0);    // texel floor(1.2) = 1
    CHECK(reference::sample_2d(row, s, false, {-0.10, 0.5}).r == 3.0);   // repeat: -0.4 -> texel 3
    s.wrap_s = GL_MIRRORED_REPEAT;
    CHECK(reference::sample_2d(row, s, false, {-0.10, 0.5}).r == 0.0);   // mirror: texel -1 -> 0
    CHECK(reference::sample_2d(row, s, false, {1.30, 0.5}).r == 2.0);    // texel 5 -> 2
    s.wrap_s = GL_CLAMP_TO_EDGE;
    CHECK(reference::sample_2d(row, s, false, {1.30, 0.5}).r == 3.0);
    s.min_filter = s.mag_filter = GL_LINEAR;
    CHECK(reference::sample_2d(row, s, false, {0.375, 0.5}).r == doctest::Approx(1.0));  // texel centre 1.5/4
    CHECK(reference::sample_2d(row, s, false, {0.5, 0.5}).r == doctest::Approx(1.5));    // halfway between 1 and 2
    CHECK(reference::sample_2d(row, s, false, {0.0, 0.5}).r == doctest::Approx(0.0));    // clamped edge
    s.wrap_s = GL_REPEAT;
    CHECK(reference::sample_2d(row, s, false, {0.0, 0.5}).r == doctest::Approx(1.5));    // between texels 3 and 0
    s.min_filter = GL_LINEAR_MIPMAP_LINEAR;
    CHECK_THROWS_AS(reference::sample_2d(row, s, false, {0.5, 0.5}), Error);
}

TEST_CASE("a missing texture's stand-in follows its name: normal maps by word, not by any letters that spell one") {
    // The real legacy corpus: XToon.cgfx's XToonMap got a flat normal map ("toon map" holds "nmap")
    // and its toon shading came out one flat colour.
    CHECK(texture::placeholder_kind(texture::TextureType::Tex2D, "XToonMap") == "grey checker");
    CHECK(texture::placeholder_kind(texture::TextureType::Tex2D, "nmapTex") == "flat normal map");
    CHECK(texture::placeholder_kind(texture::TextureType::Tex2D, "bump_nmap") == "flat normal map");
    CHECK(texture::placeholder_kind(texture::TextureType::Tex2D, "objectNMap") == "flat normal map");
    CHECK(texture::placeholder_kind(texture::TextureType::Tex2D, "NormalTexture") == "flat normal map");
    CHECK(texture::placeholder_kind(texture::TextureType::Cube, "envMap") == "grey cube");
}

TEST_CASE("a missing Radiance texture's stand-in decodes as RGBE to its own grey") {
    // scene_tonemap.fx of the NVIDIA library decodes an RGBE .hdr itself: the opaque checker's alpha
    // 255 made exponent 127 (values near 1e38, a white screen); alpha 128 is exponent 0.
    const texture::TextureData data = texture::placeholder_texture(texture::TextureType::Tex2D, "HDRTexture", "nvlobby_new.hdr");
    CHECK(texture::placeholder_kind(texture::TextureType::Tex2D, "HDRTexture", "nvlobby_new.hdr") == "grey checker (RGBE-encoded)");
    bool exponent_zero = true;
    for (size_t i = 3; i < data.faces[0][0].bytes.size(); i += 4) exponent_zero = exponent_zero && data.faces[0][0].bytes[i] == 128;
    CHECK(exponent_zero);
    CHECK(texture::placeholder_texture(texture::TextureType::Tex2D, "HDRTexture", "lobby.png").faces[0][0].bytes[3] == 255);
}
