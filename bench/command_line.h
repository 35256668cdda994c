#pragma once
// The command line both benchmark programs share: Google Benchmark's own flags, plus --isa,
// which picks the wavetrace kernels to measure. Google Benchmark rejects flags it does not know,
// so --isa is taken out of argv before benchmark::Initialize sees it.

#include <string>
#include <vector>

#include "kernels/isa/intersect_kernels.h"

namespace wt::bench {

struct BenchCommandLine {
    std::vector<Isa> isas;               // the kernel ISAs to register benchmarks for
    std::vector<std::string> arguments;  // what is left for Google Benchmark, program name first
};

// --isa=scalar|sse4|avx2|avx512: that ISA alone (this CPU must run it); --isa=auto: the best ISA
// this CPU runs; --isa=all (the default): every ISA this CPU runs. The last --isa wins.
// default_min_time_seconds becomes --benchmark_min_time unless the user gave one: a default
// set on the command line, unlike Benchmark::MinTime(), is not appended to every benchmark's
// name and still lets the user ask for shorter or longer runs.
// Throws std::invalid_argument with a message for the user.
BenchCommandLine parse_bench_command_line(int argc, char** argv, double default_min_time_seconds);

// Hands the remaining arguments to Google Benchmark and runs every registered benchmark they
// select. Returns main's exit status (2 for an argument Google Benchmark does not know).
int run_registered_benchmarks(const BenchCommandLine& command_line);

}  // namespace wt::bench
