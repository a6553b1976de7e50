// Every texture reader, chosen as fxview chooses them, by the file's extension: the first byte of
// the input picks the format, the rest is the file.
#include "fuzz_input.hpp"
#include "texture/texture_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, size_t size) {
    static const char* const extensions[] = {".png", ".jpg", ".bmp", ".tga", ".hdr", ".exr", ".dds", ".ftxt"};
    if (size == 0) return 0;
    const std::string path = fxview::fuzz::write_input(data + 1, size - 1, std::string("texture") + extensions[data[0] % 8]);
    fxview::fuzz::expect_only_fxview_errors([&] {
        const auto texture = fxview::texture::load_texture_file(path);
        // What effects do with a texture next: cube crosses, 1D and 3D views.
        fxview::fuzz::expect_only_fxview_errors([&] { fxview::texture::split_cube_cross(texture); });
        fxview::fuzz::expect_only_fxview_errors([&] { fxview::texture::as_1d(texture); });
        fxview::fuzz::expect_only_fxview_errors([&] { fxview::texture::as_3d(texture, 2); });
    });
    return 0;
}
