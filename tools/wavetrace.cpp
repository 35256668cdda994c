// wavetrace: the command-line front end. Subcommands live in their own files.

#include <CLI/CLI.hpp>

#include "merge_command.h"
#include "render_command.h"

int main(int argc, char** argv) {
    CLI::App app{"wavetrace: a wavefront Monte Carlo path tracer for the CPU"};
    app.require_subcommand(1);
    wt::RenderCommandOptions render_options;
    CLI::App* render = wt::add_render_command(app, render_options);
    wt::MergeCommandOptions merge_options;
    CLI::App* merge = wt::add_merge_command(app, merge_options);
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e);
    }
    if (render->parsed()) return wt::run_render_command(render_options);
    if (merge->parsed()) return wt::run_merge_command(merge_options);
    return 1;
}
