// libFuzzer target: the command line of `wavetrace render`, parsed as the program parses it
// (the input is the arguments, separated by NUL bytes). Only parsing: a valid command line
// is not run. CLI11's ParseError is the expected way to refuse one.

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "tools/cli/cli_values.h"
#include "tools/render/render_command_options.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
    std::vector<std::string> args;
    std::string current;
    for (std::size_t i = 0; i < size; ++i) {
        if (data[i] == 0) args.push_back(current), current.clear();
        else current += char(data[i]);
    }
    args.push_back(current);
    CLI::App app{"wavetrace"};
    app.require_subcommand(1);
    app.failure_message(wt::printable_failure_message);
    wt::RenderCommandOptions options;
    wt::add_render_command(app, options);
    std::vector<std::string> reversed(args.rbegin(), args.rend());  // CLI11 takes them last first
    try {
        app.parse(reversed);
    } catch (const CLI::ParseError& e) {
        (void)wt::printable_failure_message(&app, e);
    }
    return 0;
}
