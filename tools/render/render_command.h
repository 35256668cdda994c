#pragma once
// `wavetrace render`: the command itself, run on the options its command line gave
// (render_command_options.h).

#include <CLI/CLI.hpp>

#include "tools/cli/subcommand.h"
#include "tools/render/render_command_options.h"

namespace wt {

// Runs the command; returns the process exit code. Errors are printed, never thrown.
int run_render_command(RenderCommandOptions& options);

// add_render_command and run_render_command in one, the options owned by the returned command.
Subcommand render_subcommand(CLI::App& app);

}  // namespace wt
