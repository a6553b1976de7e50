#include <iostream>

#include "app/commands.hpp"
#include "app/effect_options.hpp"
#include "context/context.hpp"
#include "effect/effect_program.hpp"
#include "effect/parser.hpp"
#include "render/effect_resources.hpp"

namespace fxview::app {

CommandRunner add_check_command(CLI::App& app) {
    struct Options {
        std::vector<std::string> paths;
        std::string backend = "egl";
    };
    auto options = std::make_shared<Options>();
    CLI::App* command = app.add_subcommand(
        "check", "Parse effects and compile every technique; print each error as file:line: message");
    command->add_option("effects", options->paths, "Effect files")->required();
    command->add_option("--backend", options->backend, "GL context used to compile")->capture_default_str();
    return [options] {
        context::ContextOptions context_options;
        context_options.backend = context::parse_backend(options->backend);
        context_options.window_visible = false;
        const auto context = context::create_context(context_options);
        int failures = 0;
        for (const auto& path : options->paths) {
            try {
                const effect::Effect effect = effect::load_effect(path, effect_load_options());
                int broken = 0;
                for (const auto& technique : effect.techniques) {
                    try {
                        effect::compile_technique(effect, technique);
                    } catch (const effect::EffectError& error) {
                        std::cout << error.what();
                        if (std::string(error.what()).back() != '\n') std::cout << "\n";
                        ++broken;
                    }
                }
                try {  // textures: every file found, readable and of the declared shape
                    render::EffectResources resources(effect, effect::default_values(effect), texture_folders());
                } catch (const effect::EffectError& error) {
                    std::cout << error.what() << "\n";
                    ++broken;
                }
                if (broken == 0) std::cout << path << ": ok (" << effect.techniques.size() << " techniques)\n";
                failures += broken;
            } catch (const effect::EffectError& error) {
                std::cout << error.what() << "\n";
                ++failures;
            }
        }
        return failures == 0 ? 0 : 1;
    };
}

}  // namespace fxview::app
