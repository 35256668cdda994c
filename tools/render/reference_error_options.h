#pragma once
// `wavetrace render --reference REF [--error-csv FILE]`: the two options as parsed from the
// command line, and their declaration on it. Kept apart from the log that uses them
// (reference_error.h), which needs the renderer, so that declaring them does not.

#include <optional>
#include <string>

#include <CLI/CLI.hpp>

namespace wt {

struct ReferenceErrorOptions {
    std::optional<std::string> reference_path, csv_path;
};

void add_reference_error_options(CLI::App& render_command, ReferenceErrorOptions& options);

}  // namespace wt
