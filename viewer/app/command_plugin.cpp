// `fxview plugin list|run`: the plugins an effect declares, run headless exactly as the viewer runs
// them (docs/plugins.md). No GL is needed: a plugin reads the effect's values and data files.
#include <cstdio>
#include <iostream>

#include <nlohmann/json.hpp>

#include "app/commands.hpp"
#include "app/effect_options.hpp"
#include "effect/parser.hpp"
#include "effect/preset.hpp"
#include "image/image_file.hpp"
#include "plugin/plugin.hpp"

namespace fxview::app {
namespace {

struct Loaded {
    effect::Effect effect;
    effect::ParameterValues values;
    std::string technique;
};

// The effect with its preset and --set values applied, as `render` would use them.
Loaded load(const EffectOptions& options) {
    Loaded loaded{effect::load_effect(options.path, effect_load_options(options)), {}, options.technique};
    loaded.values = effect::default_values(loaded.effect);
    if (!options.preset.empty()) {
        const effect::Preset preset = effect::load_preset(options.preset, loaded.effect, loaded.values);
        if (loaded.technique.empty()) loaded.technique = preset.technique;
    }
    for (const auto& assignment : options.sets) effect::set_value_from_text(loaded.effect, loaded.values, assignment);
    effect::check_constraints(loaded.effect, loaded.values);
    if (loaded.technique.empty()) loaded.technique = loaded.effect.default_technique().name;
    return loaded;
}

}  // namespace

CommandRunner add_plugin_command(CLI::App& app) {
    struct Options {
        EffectOptions effect;
        std::string name, preview, data;
        bool json = false, progress = false;
    };
    auto o = std::make_shared<Options>();
    CLI::App* command = app.add_subcommand("plugin", "List or run the plugins an effect declares (e.g. its BRDF fit)");
    command->require_subcommand(1);
    CLI::App* list = command->add_subcommand("list", "List the effect's plugins: type, what they read and write");
    list->add_option("effect", o->effect.path, "Effect file")->required();
    list->add_flag("--json", o->json, "Print JSON");
    CLI::App* run = command->add_subcommand("run", "Run one plugin headless and write its results into the effect's parameters");
    add_effect_options(*run, o->effect);  // the effect file first, then the plugin's name
    run->add_option("name", o->name, "Plugin name (plugin list shows them)")->required();
    run->add_option("--data", o->data, "Run on this data file instead of the one the plugin reads (its first input)");
    run->add_option("--preview", o->preview, "Write the plugin's preview image (PNG, EXR, PFM), if it makes one");
    run->add_flag("--progress", o->progress, "Print progress to stderr");
    run->add_flag("--json", o->json, "Print the result as JSON");
    return [o, list]() -> int {
        if (o->effect.path.empty()) throw UsageError("plugin run: name the effect file");
        const Loaded loaded = load(o->effect);
        if (list->parsed()) {
            nlohmann::json all = nlohmann::json::array();
            for (const auto& plugin : plugin::create_all(loaded.effect, texture_folders())) {
                all.push_back({{"name", plugin->name()}, {"type", plugin->type()}, {"description", plugin->description()},
                               {"inputs", plugin->inputs()}, {"outputs", plugin->outputs()}});
                if (!o->json) {
                    std::printf("%s (%s): %s\n", plugin->name().c_str(), plugin->type().c_str(), plugin->description().c_str());
                    std::string reads, writes;
                    for (const auto& s : plugin->inputs()) reads += " " + s;
                    for (const auto& s : plugin->outputs()) writes += " " + s;
                    std::printf("  reads%s; writes%s\n", reads.c_str(), writes.c_str());
                }
            }
            if (o->json) std::cout << all.dump() << "\n";
            else if (all.empty()) std::printf("%s declares no plugin\n", o->effect.path.c_str());
            return 0;
        }
        const effect::PluginDeclaration* declaration = loaded.effect.find_plugin(o->name);
        if (!declaration) {
            std::string names;
            for (const auto& p : loaded.effect.plugins) names += (names.empty() ? "" : ", ") + p.name;
            throw UsageError("plugin run: " + o->effect.path + " has no plugin '" + o->name + "'" +
                             (names.empty() ? " (it declares none)" : " (it has: " + names + ")"));
        }
        const auto plugin = plugin::create(loaded.effect, *declaration, texture_folders());
        const plugin::Reporter reporter(o->progress ? [](const plugin::Progress& p) {
            std::fprintf(stderr, "%3.0f%% %s  cost %.6g\n", 100.0 * p.fraction, p.stage.c_str(), p.cost);
        } : std::function<void(const plugin::Progress&)>{});
        if (!o->data.empty() && plugin->inputs().empty()) throw UsageError("plugin run: " + plugin->name() + " reads no data file");
        const plugin::Result result = plugin->run(loaded.values, reporter, o->data);
        effect::ParameterValues values = loaded.values;
        const std::vector<std::string> missing = plugin::apply(loaded.effect, values, result);
        const std::string technique = result.technique.empty() ? loaded.technique : result.technique;
        if (!o->effect.save_preset.empty()) effect::save_preset(o->effect.save_preset, loaded.effect, technique, values);
        if (!o->preview.empty() && result.preview) image::write_image(o->preview, *result.preview);
        if (o->json) {
            nlohmann::json out{{"effect", o->effect.path}, {"plugin", plugin->name()}, {"type", plugin->type()},
                               {"parameters", result.parameters}, {"technique", technique}, {"converged", result.converged},
                               {"warnings", result.warnings}, {"summary", result.summary}, {"numbers", result.numbers}};
            std::cout << out.dump() << "\n";
        } else {
            for (const auto& line : result.summary) std::printf("%s\n", line.c_str());
            for (const auto& [name, value] : result.parameters) {
                std::printf("  %s =", name.c_str());
                for (double v : value) std::printf(" %.6g", v);
                std::printf("\n");
            }
            if (!o->preview.empty() && result.preview) std::printf("preview %s: %s\n", o->preview.c_str(), result.preview_caption.c_str());
        }
        for (const auto& warning : result.warnings) std::fprintf(stderr, "fxview plugin: warning: %s\n", warning.c_str());
        for (const auto& reason : missing) std::fprintf(stderr, "fxview plugin: warning: not written: %s\n", reason.c_str());
        return 0;
    };
}

}  // namespace fxview::app
