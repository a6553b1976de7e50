// Plugin declarations and runs: the input is appended to effects/spectral/thinfilm.fx (so that it can
// declare plugins bound to real parameters, or redeclare them), every declared plugin is created,
// and film-fit plugins run on the effect's defaults (CPU only: no GL context is needed).
#include <algorithm>
#include <fstream>
#include <iterator>

#include "effect/parameter_values.hpp"
#include "effect/parser.hpp"
#include "fuzz_input.hpp"
#include "plugin/plugin.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, size_t size) {
    static const std::string base = [] {
        std::ifstream in(FXVIEW_SOURCE_EFFECTS_DIR "/spectral/thinfilm.fx");
        return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    }();
    static const int base_lines = static_cast<int>(std::count(base.begin(), base.end(), '\n')) + 1;
    const std::string text = base + "\n" + std::string(reinterpret_cast<const char*>(data), size);
    const std::string path = fxview::fuzz::write_input(reinterpret_cast<const std::uint8_t*>(text.data()), text.size(), "plugin.fx");
    fxview::effect::LoadOptions options;
    options.include_dirs = {FXVIEW_SOURCE_EFFECTS_DIR "/lib"};
    fxview::fuzz::expect_only_fxview_errors([&] {
        const fxview::effect::Effect effect = fxview::effect::load_effect(path, options);
        for (const auto& declaration : effect.plugins)
            fxview::fuzz::expect_only_fxview_errors([&] {
                const auto plugin = fxview::plugin::create(effect, declaration, {});
                // Runs only what the input declares (the base's own film fit would cost every execution).
                if (plugin->type() != "film-fit" || declaration.where.line <= base_lines) return;
                fxview::effect::ParameterValues values = fxview::effect::default_values(effect);
                const auto result = plugin->run(values, fxview::plugin::Reporter{}, "");
                fxview::plugin::apply(effect, values, result);
            });
    });
    return 0;
}
