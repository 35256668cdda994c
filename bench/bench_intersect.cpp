// Rays per second of the intersection kernels, and BVH build times, on every benchmark scene
// (bench_scene.h: the hexroom, and the hexroom with a 10k, 100k or 1M-triangle displaced
// sphere or a real model in it):
//   <query>/<workload>/<kernel>/<layout>/<scene>
// query closest|any, workload primary|incoherent|shadow (workloads.h), kernel an ISA of ours
// (scalar|sse4|avx2|avx512, those this CPU runs and --isa selects) or Embree's
// (embree1|embree8|embree16, when built with Embree: rtcIntersect1/8/16 and rtcOccluded1/8/16).
// Layouts of ours: bvh4 and bvh8 (the BVH of kernels/accel/bvh.h, 4 or 8 children per node, one
// ray at a time) and bvh8_packets (packets of the ISA's width, what the renderer uses for camera
// rays) on every scene; brute (ray packets over the flat primitive list, what the renderer traced
// before the BVH) and brute_primpacket (one ray against N primitives) on the hexroom only:
// brute force over 10k+ triangles takes minutes per iteration. Embree's layouts: single, raypacket.
//   build/<scene>/<bvh8|bvh4|embree>/threads:<1|2>
// times one BVH build: build_bvh() on a thread pool of that many threads, or rtcNewScene + the
// geometries + rtcCommitScene on an Embree device made with "threads=N" (the pool or device is
// made, and one build done, before timing; freeing the built tree is not timed).
//
// Every iteration of a ray benchmark traces the whole workload (640k or 1M rays) on one
// thread. Besides rays_per_second each reports checksums of its answers, `hits` and (closest
// only) `sum_t`, which must be identical for all our kernels and layouts on a scene's workload:
// every ISA gives the scalar code's bits by design, and the BVH finds the same closest hit as
// brute force, so on the hexroom bvh4, bvh8, brute and brute_primpacket must agree to the last
// digit. Embree's differ slightly (its triangle test is watertight, ours Moller-Trumbore). The
// console rounds them; --benchmark_format=json prints every digit.
//
// The any query uses each workload's own ray lengths: unbounded for primary and incoherent rays
// (so it asks "does the ray hit anything at all", which in a closed room is always yes, and
// measures how soon a kernel can stop), the distance to the light point for shadow rays.
//
// Scenes and workloads are built only when a benchmark that needs them runs
// (scene_workloads.h), and report their set-up time on stderr; a scene that cannot be built on
// this machine (the real model without assimp-testmodels) makes its benchmarks skip with the
// reason.

#include <cstdio>
#include <functional>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "bench_scene.h"
#include "command_line.h"
#include "core/base/aligned_vector.h"
#include "core/base/ray.h"
#include "core/system/thread_pool.h"
#include "kernels/accel/bvh.h"
#include "kernels/isa/intersect_dispatch.h"
#include "scene_workloads.h"
#include "workloads.h"

#ifdef WAVETRACE_HAVE_EMBREE
#include "embree_baseline.h"
#include "timed_step.h"
#endif

namespace {

using namespace wt;
using namespace wt::bench;

enum class Query { closest, any };
constexpr Query kAllQueries[] = {Query::closest, Query::any};

const char* query_name(Query query) { return query == Query::closest ? "closest" : "any"; }

enum class Layout { bvh4, bvh8, bvh8_packets, brute, brute_primpacket };
constexpr Layout kBvhLayouts[] = {Layout::bvh4, Layout::bvh8, Layout::bvh8_packets};
constexpr Layout kBruteLayouts[] = {Layout::brute, Layout::brute_primpacket};

const char* layout_name(Layout layout) {
    switch (layout) {
        case Layout::bvh4: return "bvh4";
        case Layout::bvh8: return "bvh8";
        case Layout::bvh8_packets: return "bvh8_packets";
        case Layout::brute: return "brute";
        case Layout::brute_primpacket: return "brute_primpacket";
    }
    return "unknown";
}

// The only scene small enough for brute force (30 primitives).
constexpr char kBruteForceScene[] = "hexroom";

constexpr int kBuildThreadCounts[] = {1, 2};

// Where a query's answers go: the closest-hit arrays or the occlusion flags.
struct QueryOutputs {
    AlignedVector<float> t, u, v;
    AlignedVector<uint32_t> prim;
    AlignedVector<uint8_t> occluded;

    explicit QueryOutputs(std::size_t n) : t(n), u(n), v(n), prim(n), occluded(n) {}
    HitView hits() { return {t.data(), u.data(), v.data(), prim.data()}; }
};

void report_checksums(benchmark::State& state, Query query, const QueryOutputs& out) {
    double hits = 0.0, sum_t = 0.0;
    for (std::size_t i = 0; i < out.prim.size(); ++i) {
        if (query == Query::any) {
            hits += out.occluded[i];
        } else if (out.prim[i] != kNoHit) {
            hits += 1.0;
            sum_t += double(out.t[i]);
        }
    }
    state.counters["hits"] = hits;
    if (query == Query::closest) state.counters["sum_t"] = sum_t;
}

// Runs body(scene) for the scene named `name`, or marks the benchmark skipped, with the
// reason, if the scene cannot be built here.
template <typename Body>
void with_scene(benchmark::State& state, const std::string& name, const Body& body) {
    SceneWorkloads& scene = scene_workloads(name);
    try {
        scene.scene();
    } catch (const SceneUnavailable& e) {
        state.SkipWithError(e.what());
        return;
    }
    body(scene);
}

// Runs `trace(rays, outputs)` over the whole workload once per iteration. The workload is built
// on first use, outside the timed loop, and shared with every other benchmark of the scene.
template <typename Trace>
void measure(benchmark::State& state, SceneWorkloads& scene, Query query, Workload workload, const Trace& trace) {
    const RaySet& rays = scene.rays(workload);
    const RayView view = rays.view();
    QueryOutputs out(rays.size());
    for (auto _ : state) {
        trace(view, out);
        benchmark::DoNotOptimize(out.prim.data());
        benchmark::DoNotOptimize(out.occluded.data());
        benchmark::ClobberMemory();
    }
    state.counters["rays_per_second"] = benchmark::Counter(double(rays.size()), benchmark::Counter::kIsIterationInvariantRate);
    report_checksums(state, query, out);
}

void configure(benchmark::internal::Benchmark* benchmark) {
    // Real time: a ray benchmark runs on this thread only, a build may use others, and each
    // is a fixed amount of work.
    benchmark->UseRealTime()->Unit(benchmark::kMillisecond);
}

void register_benchmark(const std::string& name, std::function<void(benchmark::State&)> run) {
    configure(benchmark::RegisterBenchmark(name.c_str(), [run](benchmark::State& state) { run(state); }));
}

std::string ray_benchmark_name(Query query, Workload workload, const std::string& kernel, const std::string& layout,
                               const std::string& scene) {
    return std::string(query_name(query)) + "/" + workload_name(workload) + "/" + kernel + "/" + layout + "/" + scene;
}

// Our kernels of `isa` in `layout` on one scene's workload.
void measure_ours(benchmark::State& state, SceneWorkloads& scene, Query query, Workload workload, const IntersectKernels& kernels,
                  Layout layout) {
    if (layout == Layout::bvh4 || layout == Layout::bvh8 || layout == Layout::bvh8_packets) {
        const BvhView bvh = bvh_view(scene.bvh(layout == Layout::bvh4 ? 4 : 8));
        const bool packets = layout == Layout::bvh8_packets;
        const auto closest = packets ? kernels.closest_bvh_packets : kernels.closest_bvh;
        const auto any = packets ? kernels.any_bvh_packets : kernels.any_bvh;
        if (query == Query::closest)
            measure(state, scene, query, workload, [&](const RayView& rays, QueryOutputs& out) { closest(bvh, rays, out.hits()); });
        else
            measure(state, scene, query, workload, [&](const RayView& rays, QueryOutputs& out) { any(bvh, rays, out.occluded.data()); });
        return;
    }
    const FlatScene flat_scene(scene.scene());
    const SceneView flat = flat_scene.view();
    const bool ray_packets = layout == Layout::brute;
    if (query == Query::closest) {
        const auto closest = ray_packets ? kernels.closest_raypacket : kernels.closest_primpacket;
        measure(state, scene, query, workload, [&](const RayView& rays, QueryOutputs& out) { closest(flat, rays, out.hits()); });
    } else {
        const auto any = ray_packets ? kernels.any_raypacket : kernels.any_primpacket;
        measure(state, scene, query, workload, [&](const RayView& rays, QueryOutputs& out) { any(flat, rays, out.occluded.data()); });
    }
}

void register_kernel_benchmarks(const std::string& scene, const std::vector<Isa>& isas) {
    std::vector<Layout> layouts(std::begin(kBvhLayouts), std::end(kBvhLayouts));
    if (scene == kBruteForceScene) layouts.insert(layouts.end(), std::begin(kBruteLayouts), std::end(kBruteLayouts));
    for (Query query : kAllQueries) {
        for (Workload workload : kAllWorkloads) {
            for (Isa isa : isas) {
                for (Layout layout : layouts) {
                    const IntersectKernels* kernels = &intersect_kernels(isa);
                    register_benchmark(ray_benchmark_name(query, workload, isa_name(isa), layout_name(layout), scene), [=](benchmark::State& state) {
                        with_scene(state, scene, [&](SceneWorkloads& workloads) { measure_ours(state, workloads, query, workload, *kernels, layout); });
                    });
                }
            }
        }
    }
}

// The BVH's size and quality, from the last build.
void report_bvh_stats(benchmark::State& state, const BvhStats& stats) {
    state.counters["primitives"] = double(stats.primitive_count);
    state.counters["nodes"] = double(stats.node_count);
    state.counters["leaves"] = double(stats.leaf_count);
    state.counters["sah_cost"] = stats.sah_cost;
    state.counters["node_bytes"] = double(stats.node_bytes);
    state.counters["primitive_bytes"] = double(stats.primitive_bytes);
}

void register_bvh_build_benchmarks(const std::string& scene) {
    for (int node_width : {8, 4}) {
        for (int threads : kBuildThreadCounts) {
            const std::string name = "build/" + scene + "/bvh" + std::to_string(node_width) + "/threads:" + std::to_string(threads);
            register_benchmark(name, [=](benchmark::State& state) {
                with_scene(state, scene, [&](SceneWorkloads& workloads) {
                    BvhBuildOptions options;
                    options.node_width = node_width;
                    options.threads = threads;
                    // The threads are started before timing, as Embree's device is made before
                    // its builds are timed.
                    ThreadPool pool(threads);
                    auto bvh = std::make_unique<Bvh>(build_bvh(workloads.scene(), options, &pool));
                    for (auto _ : state) {
                        state.PauseTiming();
                        bvh.reset();
                        state.ResumeTiming();
                        bvh = std::make_unique<Bvh>(build_bvh(workloads.scene(), options, &pool));
                    }
                    report_bvh_stats(state, bvh->stats());
                });
            });
        }
    }
}

#ifdef WAVETRACE_HAVE_EMBREE
// One EmbreeBaseline per scene, built on first use.
const EmbreeBaseline& embree_baseline(SceneWorkloads& scene) {
    static std::map<std::string, std::unique_ptr<EmbreeBaseline>> all;
    std::unique_ptr<EmbreeBaseline>& slot = all[scene.name()];
    if (!slot) {
        slot = timed_step(
            scene.name(), "Embree scene built", [&] { return std::make_unique<EmbreeBaseline>(scene.scene()); },
            [](const std::unique_ptr<EmbreeBaseline>&) { return std::string("one build thread"); });
    }
    return *slot;
}

void register_embree_benchmarks(const std::string& scene) {
    struct Variant {
        EmbreeApi api;
        const char* kernel;
        const char* layout;
    };
    constexpr Variant kVariants[] = {{EmbreeApi::single, "embree1", "single"},
                                     {EmbreeApi::packet8, "embree8", "raypacket"},
                                     {EmbreeApi::packet16, "embree16", "raypacket"}};
    for (Query query : kAllQueries) {
        for (Workload workload : kAllWorkloads) {
            for (const Variant& variant : kVariants) {
                const EmbreeApi api = variant.api;
                register_benchmark(ray_benchmark_name(query, workload, variant.kernel, variant.layout, scene), [=](benchmark::State& state) {
                    with_scene(state, scene, [&](SceneWorkloads& workloads) {
                        const EmbreeBaseline& embree = embree_baseline(workloads);
                        // Embree's documented hint for camera rays; the other workloads are not coherent.
                        const bool coherent = workload == Workload::primary;
                        if (query == Query::closest)
                            measure(state, workloads, query, workload,
                                    [&](const RayView& rays, QueryOutputs& out) { embree.closest(api, rays, out.hits(), coherent); });
                        else
                            measure(state, workloads, query, workload,
                                    [&](const RayView& rays, QueryOutputs& out) { embree.any(api, rays, out.occluded.data(), coherent); });
                    });
                });
            }
        }
    }
    for (int threads : kBuildThreadCounts) {
        register_benchmark("build/" + scene + "/embree/threads:" + std::to_string(threads), [=](benchmark::State& state) {
            with_scene(state, scene, [&](SceneWorkloads& workloads) {
                EmbreeSceneBuilder builder(threads);
                builder.build(workloads.scene());  // before timing: Embree starts its threads on first use
                for (auto _ : state) {
                    state.PauseTiming();
                    builder.release();
                    state.ResumeTiming();
                    builder.build(workloads.scene());
                }
            });
        });
    }
}
#endif

}  // namespace

int main(int argc, char** argv) {
    BenchCommandLine command_line;
    try {
        command_line = parse_bench_command_line(argc, argv, 0.5);
    } catch (const std::invalid_argument& e) {
        std::fprintf(stderr, "bench_intersect: %s\n", e.what());
        return 2;
    }
    for (const std::string& scene : bench_scene_names()) {
        register_kernel_benchmarks(scene, command_line.isas);
        register_bvh_build_benchmarks(scene);
#ifdef WAVETRACE_HAVE_EMBREE
        // The baseline is not one of our ISAs: --isa does not select it, --benchmark_filter=-embree drops it.
        register_embree_benchmarks(scene);
#endif
    }
    return run_registered_benchmarks(command_line);
}
