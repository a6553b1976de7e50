// Environments as the scene reads them (lighting/environment_sources.hpp): the first byte picks
// the file's format (and whether it is given as one file or as all six faces, the way a 130 KB PNG
// once reached 3 GB), the rest is the file. Budgets are small so that every budget check is reached.
#include "fuzz_input.hpp"
#include "lighting/environment_sources.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, size_t size) {
    static const char* const extensions[] = {".png", ".hdr", ".exr", ".dds", ".jpg", ".tga", ".ftxt", ".bmp"};
    if (size == 0) return 0;
    const std::string path = fxview::fuzz::write_input(data + 1, size - 1, std::string("environment") + extensions[data[0] % 8]);
    const bool six_faces = (data[0] & 8) != 0;
    std::string source = path;
    if (six_faces)
        for (int i = 0; i < 5; ++i) source += "," + path;
    fxview::ResourceLimits limits;
    limits.texture_bytes = 16 << 20;
    limits.texture_dimension = 4096;
    fxview::fuzz::expect_only_fxview_errors([&] { fxview::lighting::make_environment(source, 8, limits); });
    return 0;
}
