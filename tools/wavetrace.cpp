// wavetrace: the command-line front end. Each subcommand lives in its own folder.

#include <signal.h>

#include <cstdio>
#include <cstdlib>
#include <vector>

#include <CLI/CLI.hpp>

#include "tools/cli/cli_values.h"
#include "tools/compare/compare_command.h"
#include "tools/merge/merge_command.h"
#include "tools/render/render_command.h"
#include "tools/tradeoff/tradeoff_command.h"
#if WAVETRACE_MPI
#include "tools/render/mpi_render.h"
#endif

int main(int argc, char** argv) {
#if WAVETRACE_MPI
    wt::MpiJob mpi(argc, argv);  // only when started by mpirun with several ranks
#else
    // Under mpirun each rank would render the whole image and write the same files.
    for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"})
        if (const char* ranks = std::getenv(name); ranks && std::atoi(ranks) > 1) {
            std::fprintf(stderr, "wavetrace: error: started as one of %s MPI ranks, but built without MPI "
                                 "(configure with -DWAVETRACE_MPI=ON)\n", ranks);
            return 1;
        }
#endif
    // A file size limit (ulimit -f) makes a write fail with EFBIG, reported like a full disk;
    // by default it would kill the process in the middle of a long render instead.
    signal(SIGXFSZ, SIG_IGN);
    CLI::App app{"wavetrace: a wavefront Monte Carlo path tracer for the CPU"};
    app.require_subcommand(1);
    app.failure_message(wt::printable_failure_message);
    // Registered in this order, which is the order `--help` lists them in.
    const std::vector<wt::Subcommand> subcommands = {wt::render_subcommand(app), wt::merge_subcommand(app),
                                                     wt::compare_subcommand(app), wt::tradeoff_subcommand(app)};
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e);
    }
    for (const wt::Subcommand& s : subcommands)
        if (s.app->parsed()) return s.run();
    return 1;
}
