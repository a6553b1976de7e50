// `fxview view`: the interactive viewer as a subcommand.
#pragma once
#include "app/commands.hpp"

namespace fxview::ui {

app::CommandRunner add_view_command(CLI::App& app);

}  // namespace fxview::ui
