#pragma once
// `wavetrace tradeoff SCENE --reference REF [--budget SECONDS]`: sweeps the knobs that trade time
// for error, fits error against time per configuration, and reports the table, CSVs and the
// Pareto front (README, "The speed/accuracy trade").

#include <CLI/CLI.hpp>

#include "tools/cli/subcommand.h"

namespace wt {

Subcommand tradeoff_subcommand(CLI::App& app);

}  // namespace wt
