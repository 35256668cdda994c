// wavetrace: the command-line front end. Subcommands live in their own files.

#include <CLI/CLI.hpp>

#include "compare_command.h"
#include "render_command.h"
#include "tradeoff_command.h"

int main(int argc, char** argv) {
    CLI::App app{"wavetrace: a wavefront Monte Carlo path tracer for the CPU"};
    app.require_subcommand(1);
    wt::RenderCommandOptions render_options;
    CLI::App* render = wt::add_render_command(app, render_options);
    const std::vector<wt::Subcommand> subcommands = {wt::compare_subcommand(app), wt::tradeoff_subcommand(app)};
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e);
    }
    if (render->parsed()) return wt::run_render_command(render_options);
    for (const wt::Subcommand& s : subcommands)
        if (s.app->parsed()) return s.run();
    return 1;
}
