// Samples and rays per second of whole renders of the hexroom, as the command line runs them:
//   render/wavefront/<isa>/threads:<n>   the wavefront integrator on each kernel ISA (--isa)
//   render/reference/scalar/threads:<n>  the reference integrator, one path at a time through
//                                        the scalar intersection code whatever --isa says
//   render/progressive/<isa>/threads:<n> the wavefront integrator in the command line's passes
//                                        (1, 1, 2, 4, 8 spp): the cost of passes against one go
// on 1 and 2 threads. The image is small enough for an iteration to take about half a second
// to a second on the best ISA with 2 threads, and large enough to keep every thread busy
// (256 tiles of 16x16 pixels).

#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "bench_scene.h"
#include "command_line.h"
#include "core/film/film.h"
#include "core/scene/scene.h"
#include "kernels/isa/intersect_dispatch.h"
#include "kernels/progressive_render.h"
#include "kernels/renderer.h"

namespace {

using namespace wt;
using namespace wt::bench;

constexpr int kImageSize = 256;
constexpr int kSamplesPerPixel = 16;
constexpr int kThreadCounts[] = {1, 2};

const Scene& render_scene() {
    static const Scene scene = build_scene(hexroom_description(kImageSize, kImageSize, kSamplesPerPixel));
    return scene;
}

void measure_render(benchmark::State& state, const RenderOptions& options, bool progressive) {
    const Scene& scene = render_scene();
    RayCounts total;
    for (auto _ : state) {
        // A fresh film each time: the film accumulates, and a render always starts from an empty one.
        Film film(scene.settings.width, scene.settings.height, render_film_channels(scene, options.aovs));
        if (progressive) {
            RenderSession session(scene, options);
            ProgressiveOptions passes;
            passes.samples = {0, uint32_t(scene.settings.spp)};
            render_progressive(session, film, passes);
            total += session.result().counts;
        } else {
            total += render(scene, options, film).counts;
        }
        benchmark::DoNotOptimize(film);
    }
    // Totals over all iterations, as rates over the measured (real) time.
    state.counters["samples_per_second"] = benchmark::Counter(double(total.samples), benchmark::Counter::kIsRate);
    state.counters["rays_per_second"] = benchmark::Counter(double(total.total_rays()), benchmark::Counter::kIsRate);
}

void register_render(const std::string& kind, const std::string& isa, int threads, const RenderOptions& options) {
    const std::string name = "render/" + kind + "/" + isa + "/threads:" + std::to_string(threads);
    const bool progressive = kind == "progressive";
    benchmark::RegisterBenchmark(name.c_str(),
                                 [options, progressive](benchmark::State& state) { measure_render(state, options, progressive); })
        // Real time: the work runs on the render's own threads, not on the one Google Benchmark times.
        ->UseRealTime()
        ->Unit(benchmark::kMillisecond);
}

void register_render_benchmarks(const std::vector<Isa>& isas) {
    for (Isa isa : isas) {
        for (int threads : kThreadCounts) {
            RenderOptions options;
            options.integrator = Integrator::wavefront;
            options.threads = threads;
            options.isa = isa;
            register_render("wavefront", isa_name(isa), threads, options);
            register_render("progressive", isa_name(isa), threads, options);
        }
    }
    for (int threads : kThreadCounts) {
        RenderOptions options;
        options.integrator = Integrator::reference;
        options.threads = threads;
        register_render("reference", "scalar", threads, options);
    }
}

}  // namespace

int main(int argc, char** argv) {
    BenchCommandLine command_line;
    try {
        command_line = parse_bench_command_line(argc, argv, 1.0);
    } catch (const std::invalid_argument& e) {
        std::fprintf(stderr, "bench_render: %s\n", e.what());
        return 2;
    }
    register_render_benchmarks(command_line.isas);
    return run_registered_benchmarks(command_line);
}
