// BRDF Explorer files: the .brdf translation (effect/brdf_file.cpp), then the effect loader on its output.
#include "effect/parser.hpp"
#include "fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, size_t size) {
    const std::string path = fxview::fuzz::write_input(data, size, "effect.brdf");
    fxview::effect::LoadOptions options;
    options.include_dirs = {FXVIEW_SOURCE_EFFECTS_DIR "/lib"};
    fxview::fuzz::expect_only_fxview_errors([&] { fxview::effect::load_effect(path, options); });
    return 0;
}
