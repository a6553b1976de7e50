// JSON presets applied to a shipped effect with parameters of every kind, and their scene block
// (environment files under the file-access policy, numbers in range).
#include "effect/parameter_values.hpp"
#include "effect/parser.hpp"
#include "effect/preset.hpp"
#include "fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, size_t size) {
    static const fxview::effect::Effect effect = [] {
        fxview::effect::LoadOptions options;
        options.include_dirs = {FXVIEW_SOURCE_EFFECTS_DIR "/lib"};
        return fxview::effect::load_effect(FXVIEW_SOURCE_EFFECTS_DIR "/brdf/analytic.fx", options);
    }();
    const std::string path = fxview::fuzz::write_input(data, size, "preset.json");
    fxview::effect::ParameterValues values = fxview::effect::default_values(effect);
    fxview::fuzz::expect_only_fxview_errors([&] { fxview::effect::load_preset(path, effect, values); });
    fxview::fuzz::expect_only_fxview_errors([&] { fxview::effect::load_preset_scene(path, effect.limits, effect.access); });
    return 0;
}
