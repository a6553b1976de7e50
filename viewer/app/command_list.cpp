#include <nlohmann/json.hpp>

#include <iostream>

#include "app/commands.hpp"
#include "core/text.hpp"
#include "app/effect_options.hpp"
#include "effect/parameter_values.hpp"
#include "effect/parser.hpp"

namespace fxview::app {

namespace {

nlohmann::json value_json(const effect::Value& value) {
    if (value.is_string) return value.text;
    if (value.numbers.size() == 1) return value.numbers[0];
    return value.numbers;
}

nlohmann::json optional_json(const std::optional<double>& value) { return value ? nlohmann::json(*value) : nlohmann::json(); }

}  // namespace

CommandRunner add_list_command(CLI::App& app) {
    struct Options {
        std::string path;
        bool json = false;
        AccessOptions access;
    };
    auto options = std::make_shared<Options>();
    CLI::App* command = app.add_subcommand("list", "List an effect's techniques, passes and parameters");
    command->add_option("effect", options->path, "Effect file")->required();
    command->add_flag("--json", options->json, "Print one JSON object");
    add_access_options(*command, options->access);
    return [options] {
        const effect::Effect effect = effect::load_effect(options->path, effect_load_options(options->access));
        nlohmann::json techniques = nlohmann::json::array();
        for (const auto& technique : effect.techniques) {
            nlohmann::json passes = nlohmann::json::array();
            for (const auto& pass : technique.passes) {
                nlohmann::json shaders = nlohmann::json::object();
                for (const auto& [stage, name] : pass.shaders) shaders[effect::stage_name(stage)] = name;
                passes.push_back({{"name", pass.name}, {"shaders", shaders}, {"location", pass.where.str()}});
            }
            techniques.push_back({{"name", technique.name}, {"passes", passes}, {"location", technique.where.str()}});
        }
        nlohmann::json parameters = nlohmann::json::array();
        for (const auto& p : effect.parameters) {
            nlohmann::json annotations = nlohmann::json::object();
            for (const auto& a : p.annotations) annotations[a.name] = value_json(a.value);
            parameters.push_back({
                {"name", p.name},
                {"type", p.type},
                {"array_size", p.array_size},
                {"semantic", p.semantic.empty() ? nlohmann::json() : nlohmann::json(p.semantic)},
                {"default", p.default_value ? value_json(*p.default_value) : nlohmann::json()},
                {"label", p.ui.label.empty() ? p.name : p.ui.label},
                {"widget", p.ui.widget.empty() ? nlohmann::json() : nlohmann::json(p.ui.widget)},
                {"min", optional_json(p.ui.min)},
                {"max", optional_json(p.ui.max)},
                {"step", optional_json(p.ui.step)},
                {"group", p.ui.group},
                {"order", p.ui.order},
                {"unit", p.ui.unit},
                {"help", p.ui.help},
                {"items", p.ui.items},
                {"annotations", annotations},
                {"location", p.where.str()},
            });
        }
        if (options->json) {
            std::cout << nlohmann::json{{"effect", options->path}, {"techniques", techniques}, {"parameters", parameters}}.dump(2)
                      << "\n";
            return 0;
        }
        std::cout << options->path << "\ntechniques:\n";
        for (const auto& technique : effect.techniques) {
            std::cout << "  " << technique.name << " (" << technique.passes.size() << " pass"
                      << (technique.passes.size() == 1 ? "" : "es") << ")\n";
        }
        std::cout << "parameters:\n";
        // Range and default where the effect gives them, as the UI shows them.
        for (size_t i = 0; i < effect.parameters.size(); ++i) {
            const effect::Parameter& p = effect.parameters[i];
            std::cout << "  " << p.type << " " << p.name << (p.semantic.empty() ? "" : " : " + p.semantic);
            if (!p.ui.label.empty() && p.ui.label != p.name) std::cout << "  \"" << excerpt(p.ui.label, 80) << "\"";
            if (p.ui.min || p.ui.max)
                std::cout << "  range " << (p.ui.min ? parameters[i]["min"].dump() : "-") << ".." << (p.ui.max ? parameters[i]["max"].dump() : "-");
            if (p.default_value) {
                const nlohmann::json& value = parameters[i]["default"];
                std::cout << "  default ";
                if (p.type == "bool") std::cout << (value == 0.0 ? "false" : "true");
                else if (p.type == "int" && value.is_number()) std::cout << static_cast<long long>(value.get<double>());
                else std::cout << value.dump();
            }
            std::cout << "\n";
        }
        return 0;
    };
}

}  // namespace fxview::app
