// Rays per second of the intersection kernels on the hexroom, for every
//   <query>/<workload>/<kernel>/<layout>
// query closest|any, workload primary|incoherent|shadow (workloads.h), kernel an ISA of ours
// (scalar|sse4|avx2|avx512, those this CPU runs and --isa selects) or Embree's
// (embree1|embree8|embree16, when built with Embree), layout raypacket|primpacket for ours,
// single|raypacket for Embree's.
//
// Every iteration traces the whole workload (640k or 1M rays) on one thread. Besides
// rays_per_second each benchmark reports checksums of its answers, `hits` and (closest only)
// `sum_t`, which must be identical for all our kernels on a workload (they are bit-identical
// by design); Embree's differ slightly (its triangle test is watertight, ours Moller-Trumbore).
// The console rounds them; --benchmark_format=json prints every digit.
//
// The any query uses each workload's own ray lengths: unbounded for primary and incoherent rays
// (so it asks "does the ray hit anything at all", which in a closed room is always yes, and
// measures how soon a kernel can stop), the distance to the light point for shadow rays.

#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "command_line.h"
#include "core/aligned_vector.h"
#include "core/ray.h"
#include "kernels/intersect_dispatch.h"
#include "workloads.h"

#ifdef WAVETRACE_HAVE_EMBREE
#include "embree_baseline.h"
#endif

namespace {

using namespace wt;
using namespace wt::bench;

enum class Query { closest, any };
constexpr Query kAllQueries[] = {Query::closest, Query::any};

const char* query_name(Query query) { return query == Query::closest ? "closest" : "any"; }

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

// Runs `trace(rays, outputs)` over the whole workload once per iteration. The workload is built
// on first use, outside the timed loop, and shared with every other benchmark.
template <typename Trace>
void measure(benchmark::State& state, Query query, Workload workload, const Trace& trace) {
    const RaySet& rays = workload_rays(workload);
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
    // Real time: the kernels run on this thread only, and a workload is a fixed amount of work.
    benchmark->UseRealTime()->Unit(benchmark::kMillisecond);
}

std::string benchmark_name(Query query, Workload workload, const std::string& kernel, const std::string& layout) {
    return std::string(query_name(query)) + "/" + workload_name(workload) + "/" + kernel + "/" + layout;
}

void register_kernel_benchmarks(const std::vector<Isa>& isas) {
    enum class Layout { raypacket, primpacket };
    for (Query query : kAllQueries) {
        for (Workload workload : kAllWorkloads) {
            for (Isa isa : isas) {
                for (Layout layout : {Layout::raypacket, Layout::primpacket}) {
                    const IntersectKernels* kernels = &intersect_kernels(isa);
                    const bool ray_packets = layout == Layout::raypacket;
                    const std::string name = benchmark_name(query, workload, isa_name(isa), ray_packets ? "raypacket" : "primpacket");
                    configure(benchmark::RegisterBenchmark(name.c_str(), [=](benchmark::State& state) {
                        const SceneView scene = scene_view(benchmark_scene());
                        if (query == Query::closest) {
                            const auto closest = ray_packets ? kernels->closest_raypacket : kernels->closest_primpacket;
                            measure(state, query, workload, [&](const RayView& rays, QueryOutputs& out) { closest(scene, rays, out.hits()); });
                        } else {
                            const auto any = ray_packets ? kernels->any_raypacket : kernels->any_primpacket;
                            measure(state, query, workload, [&](const RayView& rays, QueryOutputs& out) { any(scene, rays, out.occluded.data()); });
                        }
                    }));
                }
            }
        }
    }
}

#ifdef WAVETRACE_HAVE_EMBREE
const EmbreeBaseline& embree_hexroom() {
    static const EmbreeBaseline embree(benchmark_scene());
    return embree;
}

void register_embree_benchmarks() {
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
                configure(benchmark::RegisterBenchmark(
                    benchmark_name(query, workload, variant.kernel, variant.layout).c_str(), [=](benchmark::State& state) {
                        const EmbreeBaseline& embree = embree_hexroom();
                        // Embree's documented hint for camera rays; the other workloads are not coherent.
                        const bool coherent = workload == Workload::primary;
                        if (query == Query::closest)
                            measure(state, query, workload, [&](const RayView& rays, QueryOutputs& out) { embree.closest(api, rays, out.hits(), coherent); });
                        else
                            measure(state, query, workload, [&](const RayView& rays, QueryOutputs& out) { embree.any(api, rays, out.occluded.data(), coherent); });
                    }));
            }
        }
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
    register_kernel_benchmarks(command_line.isas);
#ifdef WAVETRACE_HAVE_EMBREE
    // The baseline is not one of our ISAs: --isa does not select it, --benchmark_filter=-embree drops it.
    register_embree_benchmarks();
#endif
    return run_registered_benchmarks(command_line);
}
