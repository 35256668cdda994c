#pragma once
// `wavetrace compare IMAGE REFERENCE [--mask MASK]`: the error of an image against a reference.

#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "tools/cli/subcommand.h"

namespace wt {

struct CompareCommandOptions {
    std::string image_path, reference_path;
    std::optional<std::string> mask_path;
};

CLI::App* add_compare_command(CLI::App& app, CompareCommandOptions& options);

// Returns the exit code: 0, or 1 after printing an error naming the file.
int run_compare_command(const CompareCommandOptions& options);

// Both of the above, the options owned by the returned command.
Subcommand compare_subcommand(CLI::App& app);

}  // namespace wt
