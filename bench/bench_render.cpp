// Samples and rays per second of whole renders of the hexroom, as the command line runs them:
//   render/wavefront/<isa>/threads:<n>   the wavefront integrator on each kernel ISA (--isa)
//   render/reference/scalar/threads:<n>  the reference integrator, one path at a time through
//                                        the scalar intersection code whatever --isa says
//   render/progressive/<isa>/threads:<n> the wavefront integrator in the command line's passes
//                                        (1, 1, 2, 4, 8 spp): the cost of passes against one go
//   render/<scene>/<isa>/threads:<n>     the wavefront integrator on the hexroom with a benchmark
//                                        mesh (bench_scene.h: hexroom_mesh10k, hexroom_mesh1m),
//                                        through the BVH the automatic choice builds; skipped
//                                        until the bench_data target has written the meshes
// on 1 and 2 threads. The image is small enough for an iteration to take about half a second
// to a second on the best ISA with 2 threads, and large enough to keep every thread busy
// (256 tiles of 16x16 pixels). A meshed scene is loaded and built once, outside the timing;
// its BVH is built in every iteration, as a render builds it.

#include <cstdio>
#include <map>
#include <memory>
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

constexpr const char* kHexroom = "hexroom";
// The meshed scenes rendered besides the hexroom: the BVH's cost in a render, against the
// hexroom's flat list.
constexpr const char* kMeshedScenes[] = {"hexroom_mesh10k", "hexroom_mesh1m"};

// The scene `name` at the benchmark's size, built on first use. Throws SceneUnavailable.
const Scene& render_scene(const std::string& name) {
    static std::map<std::string, std::unique_ptr<Scene>> built;
    std::unique_ptr<Scene>& scene = built[name];
    if (!scene) {
        SceneDescription d = name == kHexroom ? hexroom_description(kImageSize, kImageSize, kSamplesPerPixel)
                                              : bench_scene(name, kImageSize, kImageSize).description;
        d.settings.spp = kSamplesPerPixel;
        scene = std::make_unique<Scene>(build_scene(d));
    }
    return *scene;
}

void measure_render(benchmark::State& state, const std::string& scene_name, const RenderOptions& options, bool progressive) {
    const Scene* found = nullptr;
    try {
        found = &render_scene(scene_name);
    } catch (const SceneUnavailable& e) {
        state.SkipWithError(e.what());
        return;
    }
    const Scene& scene = *found;
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

// `kind`: wavefront, progressive or reference on the hexroom, or the name of a meshed scene
// (the wavefront integrator).
void register_render(const std::string& kind, const std::string& isa, int threads, const RenderOptions& options) {
    const std::string name = "render/" + kind + "/" + isa + "/threads:" + std::to_string(threads);
    const bool progressive = kind == "progressive";
    const bool meshed = kind != "wavefront" && kind != "progressive" && kind != "reference";
    const std::string scene = meshed ? kind : kHexroom;
    benchmark::RegisterBenchmark(name.c_str(), [scene, options, progressive](benchmark::State& state) {
        measure_render(state, scene, options, progressive);
    })
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
            for (const char* scene : kMeshedScenes) register_render(scene, isa_name(isa), threads, options);
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
