#include <nlohmann/json.hpp>

#include <iostream>

#include "app/commands.hpp"
#include "context/context.hpp"

namespace fxview::app {

CommandRunner add_info_command(CLI::App& app) {
    struct Options {
        std::string backend = "egl";
        bool json = false;
    };
    auto options = std::make_shared<Options>();
    CLI::App* command = app.add_subcommand("info", "Print the GL vendor, renderer and version of a backend");
    command->add_option("--backend", options->backend, "egl, egl-device, osmesa or glfw")->capture_default_str();
    command->add_flag("--json", options->json, "Print one JSON object");
    return [options] {
        context::ContextOptions context_options;
        context_options.backend = context::parse_backend(options->backend);
        context_options.window_visible = false;
        const auto context = context::create_context(context_options);
        const context::ContextInfo info = context::query_context_info();
        if (options->json) {
            std::cout << nlohmann::json{{"backend", options->backend},
                                        {"vendor", info.vendor},
                                        {"renderer", info.renderer},
                                        {"version", info.version},
                                        {"glsl_version", info.glsl_version},
                                        {"major", info.major},
                                        {"minor", info.minor},
                                        {"core_profile", info.core_profile}}
                             .dump()
                      << "\n";
        } else {
            std::cout << "backend:  " << options->backend << "\nvendor:   " << info.vendor
                      << "\nrenderer: " << info.renderer << "\nversion:  " << info.version
                      << "\nGLSL:     " << info.glsl_version << "\nprofile:  " << (info.core_profile ? "core" : "compatibility")
                      << "\n";
        }
        return 0;
    };
}

}  // namespace fxview::app
