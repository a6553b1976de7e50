#include "app/effect_options.hpp"

#include <cstdlib>
#include <filesystem>

#include "effect/preset.hpp"
#include "spectral/library.hpp"

namespace fxview::app {

void add_effect_options(CLI::App& command, EffectOptions& options) {
    command.add_option("effect", options.path, "Effect file (.fx); without one the built-in debug shader draws");
    command.add_option("--technique,-t", options.technique, "Technique to render (default: the first)");
    command.add_option("--set", options.sets, "Parameter value NAME=VALUE (0.5 | 1,0,0 | #rrggbb | true | FILE for a sampler)")
        ->allow_extra_args(false);
    command.add_option("--preset", options.preset, "Load parameter values from a JSON preset (before --set)");
    command.add_option("--save-preset", options.save_preset, "Save the parameter values used as a JSON preset");
}

effect::LoadOptions effect_load_options() {
    const char* override_dir = std::getenv("FXVIEW_EFFECTS_DIR");
    const std::filesystem::path root = override_dir ? override_dir : FXVIEW_SOURCE_EFFECTS_DIR;
    effect::LoadOptions options{{(root / "lib").string()}, {}};
    // Spectrum parameters (UIItems = "spectral:library") list the library's names, so that
    // `--set LightSpectrum=D65` works; a missing or broken library only leaves them as numbers.
    const char* spectra_dir = std::getenv("FXVIEW_SPECTRA_DIR");
    try {
        const auto library = spectral::load_library(std::string(spectra_dir ? spectra_dir : FXVIEW_SOURCE_SPECTRA_DIR) + "/library.txt");
        for (const auto& entry : library.entries) options.item_lists["spectral:library"].push_back(entry.named.name);
    } catch (const std::exception&) {
    }
    return options;
}

std::unique_ptr<render::EffectSession> open_effect_session(const EffectOptions& options) {
    auto session = std::make_unique<render::EffectSession>(options.path, effect_load_options(), texture_folders());
    if (!options.technique.empty()) session->select_technique(options.technique);
    if (!options.preset.empty()) {
        const effect::Preset preset = effect::load_preset(options.preset, session->effect(), session->values());
        // The preset's technique applies unless the command line names one.
        if (options.technique.empty() && !preset.technique.empty()) session->select_technique(preset.technique);
    }
    for (const auto& assignment : options.sets) effect::set_value_from_text(session->effect(), session->values(), assignment);
    if (!session->values().textures.empty()) session->reload_textures();
    return session;
}

std::vector<std::string> texture_folders() {
    const char* override_dir = std::getenv("FXVIEW_TEXTURES_DIR");
    return {override_dir ? override_dir : FXVIEW_SOURCE_TEXTURES_DIR};
}

}  // namespace fxview::app
