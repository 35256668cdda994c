#pragma once
// `wavetrace merge PART... -o OUT...`: the partial renders of a split render (`render
// --samples`) into one image or checkpoint, after checking they are parts of one render.

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "tools/cli/subcommand.h"

namespace wt {

struct MergeCommandOptions {
    std::vector<std::string> parts;
    std::vector<std::string> outputs;
    bool allow_gaps = false;
    bool quiet = false;
};

CLI::App* add_merge_command(CLI::App& app, MergeCommandOptions& options);

// Returns the exit code: 0 merged, 1 an error (printed; nothing written).
int run_merge_command(const MergeCommandOptions& options);

// Both of the above, the options owned by the returned command.
Subcommand merge_subcommand(CLI::App& app);

}  // namespace wt
