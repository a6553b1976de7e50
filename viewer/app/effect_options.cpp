#include "app/effect_options.hpp"

#include <iostream>

#include <cstdlib>
#include <filesystem>

#include "core/error.hpp"
#include "core/text.hpp"
#include "effect/preset.hpp"
#include "spectral/library.hpp"

namespace fxview::app {

void add_effect_options(CLI::App& command, EffectOptions& options) {
    command.add_option("effect", options.path, "Effect file (.fx); without one the built-in debug shader draws");
    command.add_option("--technique,-t", options.technique, "Technique to render (default: the effect's Default technique, else the first)");
    command.add_option("--set", options.sets, "Parameter value NAME=VALUE (0.5 | 1,0,0 | #rrggbb | true | FILE for a sampler)")
        ->allow_extra_args(false);
    command.add_option("--preset", options.preset, "Load parameter values from a JSON preset or a BRDF Explorer .bparam (before --set)");
    command.add_option("--save-preset", options.save_preset, "Save the parameter values used as a JSON preset (NAME.bparam: as BRDF Explorer's parameter file)");
    command.add_option("--texture", options.textures,
                       "Texture file for a texture or a sampler NAME=FILE (replaces its ResourceName, or a legacy effect's placeholder)")
        ->allow_extra_args(false);
    add_access_options(command, options.access);
}

void add_access_options(CLI::App& command, AccessOptions& options) {
    command.add_option("--allow-path", options.allow_paths,
                       "Let effects read files below DIR too (default: only the effect's folder and the project's effects/lib, "
                       "textures/ and spectra/)");
    std::string names;
    for (const auto& info : limit_infos()) names += (names.empty() ? "" : ", ") + std::string(info.name);
    command.add_option("--limit", options.limits, "Change a resource budget NAME=VALUE (" + names + "; K/M/G suffixes)");
    command.add_option("--matrix-convention", options.matrix_convention,
                       "Cg/HLSL effects: row (DirectX, mul(v, M)) or column (OpenGL, mul(M, v)) instead of what the file says or does")
        ->check(CLI::IsMember({"row", "column"}));
}

ResourceLimits resource_limits(const AccessOptions& options) {
    ResourceLimits limits;
    for (const auto& assignment : options.limits) set_limit(limits, assignment);
    return limits;
}

effect::LoadOptions effect_load_options(const AccessOptions& access) {
    const char* override_dir = std::getenv("FXVIEW_EFFECTS_DIR");
    const std::filesystem::path root = override_dir ? override_dir : FXVIEW_SOURCE_EFFECTS_DIR;
    effect::LoadOptions options;
    options.include_dirs = {(root / "lib").string()};
    options.access.allow_folder(root / "lib");
    for (const auto& folder : texture_folders()) options.access.allow_folder(folder);
    options.access.allow_folder(spectra_folder());
    for (const auto& folder : access.allow_paths) {
        std::error_code error;
        if (!std::filesystem::is_directory(folder, error)) throw UsageError("--allow-path " + folder + ": no such folder");
        options.access.allow_folder(folder);
    }
    options.limits = resource_limits(access);
    options.matrix_convention = access.matrix_convention;
    // Spectrum parameters (UIItems = "spectral:library") list the library's names, so that
    // `--set LightSpectrum=D65` works; a missing or broken library only leaves them as numbers.
    try {
        const auto library = spectral::load_library(spectra_folder() + "/library.txt");
        for (const auto& entry : library.entries) options.item_lists["spectral:library"].push_back(entry.named.name);
    } catch (const std::exception&) {
    }
    return options;
}

effect::LoadOptions effect_load_options(const EffectOptions& options) {
    effect::LoadOptions load_options = effect_load_options(options.access);
    // A texture file named on the command line (--set Sampler=FILE) is the user's own choice.
    std::vector<std::string> assignments = options.sets;
    assignments.insert(assignments.end(), options.textures.begin(), options.textures.end());
    for (const auto& assignment : assignments)
        if (const size_t equals = assignment.find('='); equals != std::string::npos) {
            std::error_code error;
            const std::string value = assignment.substr(equals + 1);
            if (std::filesystem::is_regular_file(value, error)) load_options.access.allow_file(value);
        }
    return load_options;
}

std::unique_ptr<render::EffectSession> open_effect_session(const EffectOptions& options) {
    auto session = std::make_unique<render::EffectSession>(options.path, effect_load_options(options), texture_folders());
    for (const auto& warning : session->warnings()) std::cerr << excerpt_lines(warning) << "\n";
    if (!options.technique.empty()) session->select_technique(options.technique);
    if (!options.preset.empty()) {
        const effect::Preset preset = effect::load_preset(options.preset, session->effect(), session->values());
        for (const auto& warning : preset.warnings) std::cerr << excerpt_lines(warning) << "\n";
        // The preset's technique applies unless the command line names one.
        if (options.technique.empty() && !preset.technique.empty()) session->select_technique(preset.technique);
    }
    for (const auto& assignment : options.sets) effect::set_value_from_text(session->effect(), session->values(), assignment);
    for (const auto& assignment : options.textures) {  // --texture NAME=FILE: a sampler, or a texture object by its name
        const size_t equals = assignment.find('=');
        if (equals == std::string::npos || equals == 0 || equals + 1 == assignment.size())
            throw UsageError("--texture needs NAME=FILE, got '" + excerpt(assignment) + "'");
        const std::string name = assignment.substr(0, equals);
        const effect::Parameter* sampler = session->effect().find_parameter(name);
        if (sampler && effect::is_sampler_type(sampler->type)) effect::set_value_from_text(session->effect(), session->values(), assignment);
        else if (session->effect().find_texture(name)) session->values().textures[name] = assignment.substr(equals + 1);
        else throw UsageError("--texture: the effect has no texture or sampler '" + excerpt(name) + "'");
    }
    effect::check_constraints(session->effect(), session->values());
    if (!session->values().textures.empty()) session->reload_textures();
    return session;
}

std::string spectra_folder() {
    const char* override_dir = std::getenv("FXVIEW_SPECTRA_DIR");
    return override_dir ? override_dir : FXVIEW_SOURCE_SPECTRA_DIR;
}

std::vector<std::string> texture_folders() {
    const char* override_dir = std::getenv("FXVIEW_TEXTURES_DIR");
    return {override_dir ? override_dir : FXVIEW_SOURCE_TEXTURES_DIR};
}

}  // namespace fxview::app
