#include <iostream>

#include "app/commands.hpp"
#include "core/text.hpp"
#include "app/effect_options.hpp"
#include "context/context.hpp"
#include "effect/effect_program.hpp"
#include "effect/parser.hpp"
#include "effect/preset.hpp"
#include "image/display_transform.hpp"
#include "plugin/plugin.hpp"
#include "render/effect_resources.hpp"

namespace fxview::app {

namespace {

// Prints an error as it is ("file:line: message", one or several lines).
void print_error(const std::string& message) {
    constexpr size_t kMax = 65536;  // compiler logs can be long; a hostile file must not make them endless
    const std::string shown = message.size() <= kMax ? message : message.substr(0, kMax) + "\n... (messages cut at 64 KB)";
    std::cout << shown;
    if (shown.empty() || shown.back() != '\n') std::cout << "\n";
}

// Checks one effect; returns the number of problems found. Nothing a file does stops the check of
// the next file: every exception is reported against the file it came from.
// A preset against the effect (docs/preset.schema.json): known keys only, every value by the rule of
// values, the technique the effect's, the scene's files readable under the effect's policy.
int check_preset(const std::string& preset_path, const effect::Effect& effect) {
    try {
        effect::ParameterValues values = effect::default_values(effect);
        const effect::Preset preset = effect::load_preset(preset_path, effect, values);
        if (!preset.technique.empty() && !effect.find_technique(preset.technique))
            throw Error(preset_path + ":1: preset technique '" + excerpt(preset.technique) + "' is not one of " + effect.path + "'s");
        FileAccessPolicy access = effect.access;
        const effect::PresetScene scene = effect::load_preset_scene(preset_path, effect.limits, access);
        if (scene.tone_map) try {
                image::parse_tone_map(*scene.tone_map);
            } catch (const UsageError& error) {
                throw Error(scene.where("tone_map") + error.what());
            }
        std::cout << preset_path << ": ok (preset of " << effect.path << ")\n";
        return 0;
    } catch (const std::exception& error) {
        print_error(error.what());
        return 1;
    }
}

int check_effect(const std::string& path, const effect::LoadOptions& load_options, bool dump, const std::string& preset) {
    try {
        const effect::Effect effect = effect::load_effect(path, load_options);
        if (dump)
            for (const auto& technique : effect.techniques)
                for (const auto& pass : technique.passes)
                    for (const auto& [stage, name] : pass.shaders)
                        std::cout << "// ---- " << path << ": technique " << technique.name << ", pass " << pass.name << ", "
                                  << effect::stage_name(stage) << " stage\n" << effect::assemble_stage(effect, pass, stage) << "\n";
        for (const auto& warning : effect.warnings) std::cout << excerpt_lines(warning) << "\n";
        int broken = 0;
        std::string compile_errors;  // every technique's, folded where they repeat (shared code)
        for (const auto& technique : effect.techniques) {
            try {
                effect::compile_technique(effect, technique);
            } catch (const effect::EffectError& error) {
                compile_errors += std::string(error.what()) + "\n";
                ++broken;
            }
        }
        if (!compile_errors.empty()) print_error(effect::fold_repeated_messages(compile_errors));
        try {  // textures: every file found, readable, allowed and of the declared shape
            render::EffectResources resources(effect, effect::default_values(effect), texture_folders());
            for (const auto& warning : resources.warnings()) std::cout << excerpt_lines(warning) << "\n";
        } catch (const effect::EffectError& error) {
            print_error(error.what());
            ++broken;
        }
        for (const auto& declaration : effect.plugins) {
            try {  // a plugin's type and bindings (targets, data sampler) against the effect
                plugin::create(effect, declaration, texture_folders());
            } catch (const effect::EffectError& error) {
                print_error(error.what());
                ++broken;
            }
        }
        if (broken == 0)
            std::cout << path << ": ok (" << effect.techniques.size() << " techniques"
                      << (effect.plugins.empty() ? "" : ", " + std::to_string(effect.plugins.size()) + " plugins") << ")\n";
        if (!preset.empty()) broken += check_preset(preset, effect);
        return broken;
    } catch (const effect::EffectError& error) {
        print_error(error.what());
    } catch (const std::bad_alloc&) {
        print_error(path + ":0: out of memory while checking this effect");
    } catch (const std::exception& error) {
        print_error(path + ":0: " + error.what());
    }
    return 1;
}

}  // namespace

CommandRunner add_check_command(CLI::App& app) {
    struct Options {
        std::vector<std::string> paths;
        std::string backend = "egl";
        bool dump = false;
        std::string preset;
        AccessOptions access;
    };
    auto options = std::make_shared<Options>();
    CLI::App* command = app.add_subcommand(
        "check", "Parse effects and compile every technique; print each error as file:line: message");
    command->add_option("effects", options->paths, "Effect files (each is checked and reported)")->required();
    command->add_option("--backend", options->backend, "GL context used to compile")->capture_default_str();
    command->add_flag("--dump", options->dump, "Print the GLSL of every stage as it goes to the driver (translated, for Cg/HLSL effects)");
    command->add_option("--preset", options->preset,
                        "Also check a preset against each effect: its keys (docs/preset.schema.json), values, technique and scene");
    add_access_options(*command, options->access);
    return [options] {
        const effect::LoadOptions load_options = effect_load_options(options->access);
        context::ContextOptions context_options;
        context_options.backend = context::parse_backend(options->backend);
        context_options.window_visible = false;
        const auto context = context::create_context(context_options);
        int failed_files = 0;
        for (const auto& path : options->paths) failed_files += check_effect(path, load_options, options->dump, options->preset) > 0 ? 1 : 0;
        if (options->paths.size() > 1)
            std::cout << options->paths.size() - static_cast<size_t>(failed_files) << " of " << options->paths.size() << " effects ok\n";
        return failed_files == 0 ? 0 : 1;
    };
}

}  // namespace fxview::app
