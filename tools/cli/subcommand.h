#pragma once
// A subcommand registered on the command line with the options it owns, and what running it
// does once parsed: each is one entry in main's list (tools/wavetrace.cpp).

#include <functional>

#include <CLI/CLI.hpp>

namespace wt {

struct Subcommand {
    CLI::App* app;
    std::function<int()> run;  // the process exit code
};

}  // namespace wt
