#include "command_line.h"

#include <stdexcept>

#include <benchmark/benchmark.h>

#include "kernels/isa/intersect_dispatch.h"

namespace wt::bench {

namespace {

bool starts_with(const std::string& text, const std::string& prefix) { return text.compare(0, prefix.size(), prefix) == 0; }

std::vector<Isa> isas_named(const std::string& value) {
    std::vector<Isa> isas;
    if (value == "all") {
        for (Isa isa : kAllIsas)
            if (cpu_supports(isa)) isas.push_back(isa);
    } else if (value == "auto") {
        isas.push_back(best_supported_isa());
    } else if (const std::optional<Isa> isa = parse_isa(value)) {
        // Refused rather than silently skipped: an empty run would look like a result.
        if (!cpu_supports(*isa)) throw std::invalid_argument("--isa: this CPU does not support " + value);
        isas.push_back(*isa);
    } else {
        throw std::invalid_argument("--isa: expected " + isa_names(", ") + ", auto or all, got '" + value + "'");
    }
    return isas;
}

}  // namespace

BenchCommandLine parse_bench_command_line(int argc, char** argv, double default_min_time_seconds) {
    BenchCommandLine result;
    std::string isa_value = "all";
    bool min_time_given = false;
    result.arguments.push_back(argc > 0 ? argv[0] : "bench");
    for (int i = 1; i < argc; ++i) {
        const std::string argument = argv[i];
        if (starts_with(argument, "--isa=")) {
            isa_value = argument.substr(6);
        } else if (argument == "--isa") {
            throw std::invalid_argument("--isa: write the value after '=', e.g. --isa=avx2");
        } else {
            min_time_given = min_time_given || starts_with(argument, "--benchmark_min_time");
            result.arguments.push_back(argument);
        }
    }
    result.isas = isas_named(isa_value);
    if (!min_time_given) result.arguments.push_back("--benchmark_min_time=" + std::to_string(default_min_time_seconds));
    return result;
}

int run_registered_benchmarks(const BenchCommandLine& command_line) {
    // Google Benchmark takes a mutable C argv and removes the flags it consumes.
    std::vector<std::string> storage = command_line.arguments;
    std::vector<char*> argv;
    for (std::string& argument : storage) argv.push_back(argument.data());
    argv.push_back(nullptr);
    int argc = int(storage.size());
    benchmark::Initialize(&argc, argv.data());
    if (benchmark::ReportUnrecognizedArguments(argc, argv.data())) return 2;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}

}  // namespace wt::bench
