// wavetrace: the command-line front end. Subcommands live in their own files.

#include <CLI/CLI.hpp>

#include "cli_values.h"
#include "render_command.h"

int main(int argc, char** argv) {
    CLI::App app{"wavetrace: a wavefront Monte Carlo path tracer for the CPU"};
    app.require_subcommand(1);
    app.failure_message(wt::printable_failure_message);
    wt::RenderCommandOptions render_options;
    CLI::App* render = wt::add_render_command(app, render_options);
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e);
    }
    if (render->parsed()) return wt::run_render_command(render_options);
    return 1;
}
