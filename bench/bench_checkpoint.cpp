// Checkpoint files: how large they are and how long writing (encode, checksum, fsync, rename)
// and reading (read, checksum, decode) take, at 800x800 and 4096x4096. The film holds one
// sample per pixel of varied radiance: the file's size does not depend on spp while every sum
// fits in 64 bits (below 2^23 in radiance units, checkpoint_format.h), which real renders do.
//
//   build/bin/bench_checkpoint [--benchmark_filter=...]   (writes into $TMPDIR or /tmp)

#include <unistd.h>

#include <filesystem>

#include <benchmark/benchmark.h>

#include "core/checkpoint/checkpoint.h"
#include "core/system/version.h"

namespace wt {
namespace {

namespace fs = std::filesystem;

Film film_of_side(int side) {
    Film film(side, side);
    uint64_t state = 1;
    for (uint32_t p = 0; p < film.pixel_total(); ++p) {
        state = state * 6364136223846793005ull + 1442695040888963407ull;
        const float v = float(state >> 40) / float(1 << 24);
        film.add_sample(p, glm::vec3(v, 0.5f * v, 2.0f * v));
    }
    return film;
}

CheckpointHeader header() {
    return {program_version(), 0x1234, 0, 1, 1, image_settings(RenderSettings{})};
}

std::string bench_path(int side) {
    return (fs::temp_directory_path() / ("wt_bench_checkpoint_" + std::to_string(getpid()) + "_" +
                                         std::to_string(side) + ".ckpt"))
        .string();
}

void BM_WriteCheckpoint(benchmark::State& state) {
    const int side = int(state.range(0));
    const Film film = film_of_side(side);
    const std::string path = bench_path(side);
    for (auto _ : state) write_checkpoint_file(path, header(), film);
    const double bytes = double(fs::file_size(path));
    state.counters["file_MB"] = bytes / 1e6;
    state.counters["MB/s"] = benchmark::Counter(bytes / 1e6, benchmark::Counter::kIsIterationInvariantRate);
    fs::remove(path);
}

void BM_ReadCheckpoint(benchmark::State& state) {
    const int side = int(state.range(0));
    const std::string path = bench_path(side);
    write_checkpoint_file(path, header(), film_of_side(side));
    for (auto _ : state) benchmark::DoNotOptimize(read_checkpoint_file(path));
    const double bytes = double(fs::file_size(path));
    state.counters["file_MB"] = bytes / 1e6;
    state.counters["MB/s"] = benchmark::Counter(bytes / 1e6, benchmark::Counter::kIsIterationInvariantRate);
    fs::remove(path);
}

BENCHMARK(BM_WriteCheckpoint)->Arg(800)->Arg(4096)->Unit(benchmark::kMillisecond)->Iterations(5)->UseRealTime();
BENCHMARK(BM_ReadCheckpoint)->Arg(800)->Arg(4096)->Unit(benchmark::kMillisecond)->Iterations(5)->UseRealTime();

}  // namespace
}  // namespace wt

BENCHMARK_MAIN();
