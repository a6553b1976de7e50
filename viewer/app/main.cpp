// fxview command line: subcommands for headless rendering, pixel picking and GL information.
// Exit codes: 0 success, 1 GL / I/O / data failure, 2 bad arguments.
#include <CLI/CLI.hpp>

#include <iostream>
#include <new>
#include <map>

#include "app/commands.hpp"
#include "core/error.hpp"
#include "ui/command_view.hpp"

// A message may quote what a file or argument held; none is printed beyond 8 KB.
static std::string clipped_message(const std::string& message) {
    constexpr size_t kMax = 8192;
    return message.size() <= kMax ? message : message.substr(0, kMax) + "... (message cut at 8 KB)";
}

int main(int argc, char** argv) {
    using namespace fxview;
    CLI::App app{"fxview - a shader viewer for spectral and physically based materials", "fxview"};
    app.require_subcommand(1);
    app.set_version_flag("--version", "fxview 0.1.0");
    const std::map<std::string, app::CommandRunner> runners = {
        {"render", app::add_render_command(app)},
        {"pick", app::add_pick_command(app)},
        {"info", app::add_info_command(app)},
        {"list", app::add_list_command(app)},
        {"check", app::add_check_command(app)},
        {"spectra", app::add_spectra_command(app)},
        {"compare", app::add_compare_command(app)},
        {"view", ui::add_view_command(app)},
        {"bench", app::add_bench_command(app)},
        {"fit", app::add_fit_command(app)},
        {"brdf-grid", app::add_brdf_grid_command(app)},
        {"plugin", app::add_plugin_command(app)},
        {"brdf-check", app::add_brdf_check_command(app)},
        {"brdf-plot", app::add_brdf_plot_command(app)},
    };
    if (argc > 1 && argv[1][0] != '-' && !runners.contains(argv[1])) {
        std::cerr << "fxview: unknown command '" << clipped_message(argv[1]).substr(0, 80) << "' (expected view, render, pick, info, list, check, spectra, compare or bench)\n";
        return 2;
    }
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        std::cerr << "fxview: " << clipped_message(e.what()) << "\nRun 'fxview --help' or 'fxview COMMAND --help' for usage.\n";
        return 2;
    }
    try {
        for (const CLI::App* command : app.get_subcommands()) return runners.at(command->get_name())();
        return 2;
    } catch (const UsageError& e) {
        std::cerr << "fxview: " << clipped_message(e.what()) << "\n";
        return 2;
    } catch (const std::bad_alloc&) {
        std::cerr << "fxview: error: out of memory (a file asked for more than this machine has; see --limit)\n";
        return 1;
    } catch (const std::exception& e) {
        std::cerr << "fxview: error: " << clipped_message(e.what()) << "\n";
        return 1;
    }
}
