// The subcommands of the `fxview` CLI. Each registers its options on the CLI11 app and returns the
// callback to run after a successful parse; the callback returns the process exit code.
#pragma once
#include <CLI/CLI.hpp>

#include <functional>
#include <memory>

namespace fxview::app {

using CommandRunner = std::function<int()>;

CommandRunner add_render_command(CLI::App& app);
CommandRunner add_pick_command(CLI::App& app);
CommandRunner add_info_command(CLI::App& app);
CommandRunner add_list_command(CLI::App& app);
CommandRunner add_check_command(CLI::App& app);
CommandRunner add_spectra_command(CLI::App& app);
CommandRunner add_compare_command(CLI::App& app);
CommandRunner add_bench_command(CLI::App& app);
CommandRunner add_fit_command(CLI::App& app);
CommandRunner add_brdf_grid_command(CLI::App& app);
CommandRunner add_plugin_command(CLI::App& app);
CommandRunner add_brdf_check_command(CLI::App& app);
CommandRunner add_brdf_plot_command(CLI::App& app);

}  // namespace fxview::app
