// Parameter values from text, as `--set` and the script verb `set` give them, against the shipped
// spectral and BRDF effects: every line NAME=VALUE goes through the one rule of values; whatever it
// accepts must be finite, in range and (for ints) whole, which the harness asserts.
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "effect/parameter_values.hpp"
#include "effect/parser.hpp"
#include "fuzz_input.hpp"

namespace {

fxview::effect::Effect load(const char* file) {
    fxview::effect::LoadOptions options;
    options.include_dirs = {FXVIEW_SOURCE_EFFECTS_DIR "/lib"};
    // As many names as spectra/library.txt holds at most (the shipped defaults index up to 14).
    for (int i = 0; i < 64; ++i) options.item_lists["spectral:library"].push_back("S" + std::to_string(i));
    return fxview::effect::load_effect(std::string(FXVIEW_SOURCE_EFFECTS_DIR) + file, options);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, size_t size) {
    static const fxview::effect::Effect effects[] = {load("/spectral/wavelength.fx"), load("/spectral/thinfilm.fx"), load("/spectral/cd.fx"),
                                                     load("/brdf/analytic.fx")};
    if (size == 0) return 0;
    const fxview::effect::Effect& effect = effects[data[0] % 4];
    fxview::effect::ParameterValues values = fxview::effect::default_values(effect);
    std::istringstream lines(std::string(reinterpret_cast<const char*>(data + 1), size - 1));
    for (std::string line; std::getline(lines, line);)
        fxview::fuzz::expect_only_fxview_errors([&] { fxview::effect::set_value_from_text(effect, values, line); });
    for (const auto& parameter : effect.parameters) {
        const auto value = values.numbers.find(parameter.name);
        if (value == values.numbers.end()) continue;
        if (!fxview::effect::value_problem(parameter, value->second).empty()) std::abort();  // an accepted value breaks the rule
    }
    return 0;
}
