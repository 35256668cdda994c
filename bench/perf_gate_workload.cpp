// A fixed, deterministic workload for the instruction-count performance gate (perf_gate.sh).
// Run under callgrind with --collect-atstart=no: only the region between the two
// CALLGRIND_TOGGLE_COLLECT marks is counted, so building the scene and the rays is not.
//
//   perf_gate_workload SCENE intersect ISA LAYOUT QUERY   ISA scalar|sse4|avx2, LAYOUT raypacket|primpacket,
//                                                   QUERY closest|any: 20000 incoherent hexroom rays
//                                                   LAYOUT bvh: the same rays through an 8-wide BVH
//                                                   of the hexroom plus a 9,800-triangle displaced sphere;
//                                                   bvhpackets: the same, in packets of the ISA's width;
//                                                   bvhinterleaved: eight rays' walks at a time, as a
//                                                   tree past kBvhPrefetchBytes is walked
//   perf_gate_workload SCENE build                  building that BVH on one thread
//   perf_gate_workload SCENE render ISA [AOVS]      a 24x24, 2 spp hexroom render on one thread; with
//                                                   AOVS (an --aov list: "all"), rendering those too
//   perf_gate_workload SCENE shade ISA              the shade kernels (kernels/shading) on what the
//                                                   incoherent rays hit: the surface points, then
//                                                   on the diffuse vertices one light sample
//                                                   each and the continuation past the roulette's
//                                                   start
//   perf_gate_workload SCENE shade ISA smooth       the same on the BVH cases' scene, whose sphere
//                                                   has vertex normals: shading normals blended,
//                                                   the folded BSDF at its vertices
//   perf_gate_workload SCENE lightstart ISA         the shade kernels' first rays of light paths
//                                                   (area_light_rays.h) from the scene's area lights
//   perf_gate_workload SCENE specular ISA           the shade kernels' continuation of light paths
//                                                   (specular_continuation.h) at the mirror and glass
//                                                   those rays hit, with Russian roulette

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <valgrind/callgrind.h>

#include "core/film/aov.h"
#include "core/film/film.h"
#include "core/scene/scene.h"
#include "core/scene_file/scene_loader.h"
#include "core/path/path_vertex.h"
#include "kernels/isa/intersect_dispatch.h"
#include "kernels/isa/shade_kernels.h"
#include "kernels/caustics/light_path.h"
#include "kernels/accel/scene_intersect.h"
#include "kernels/queues/light_point_queue.h"
#include "kernels/queues/specular_vertex_queue.h"
#include "kernels/queues/ray_queues.h"
#include "kernels/queues/surface_chunk.h"
#include "displaced_sphere.h"
#include "kernels/accel/bvh.h"
#include "kernels/renderer.h"

namespace {

using namespace wt;

struct Rays {
    std::vector<float> ox, oy, oz, dx, dy, dz, tmax;
    RayView view() const {
        return {ox.data(), oy.data(), oz.data(), dx.data(), dy.data(), dz.data(), tmax.data(), uint32_t(ox.size())};
    }
};

// Origins in a box inside the hexroom, uniform directions, lengths up to 15 m: the same kind
// of rays as bench_intersect's incoherent workload, fewer of them, since callgrind is slow.
Rays incoherent_rays(uint32_t count) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> x(0.5f, 9.5f), y(-4.5f, 4.5f), z(-4.5f, 4.5f), len(0.5f, 15.0f);
    std::normal_distribution<float> n;
    Rays r;
    for (uint32_t i = 0; i < count; ++i) {
        float d[3] = {n(rng), n(rng), n(rng)};
        const float inv = 1.0f / std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        r.ox.push_back(x(rng)), r.oy.push_back(y(rng)), r.oz.push_back(z(rng));
        r.dx.push_back(d[0] * inv), r.dy.push_back(d[1] * inv), r.dz.push_back(d[2] * inv);
        r.tmax.push_back(len(rng));
    }
    return r;
}

int usage() {
    std::fprintf(stderr, "usage: perf_gate_workload SCENE intersect ISA raypacket|primpacket|bvh|bvhpackets|bvhinterleaved closest|any\n"
                         "       perf_gate_workload SCENE build\n"
                         "       perf_gate_workload SCENE render ISA [AOV,...]\n"
                         "       perf_gate_workload SCENE shade ISA [smooth]\n"
                         "       perf_gate_workload SCENE lightstart ISA\n"
                         "       perf_gate_workload SCENE specular ISA\n");
    return 2;
}

// The BVH cases' scene: the hexroom plus bench_intersect's smallest mesh, so the tree has
// depth and its leaves are full.
Scene meshed_scene(SceneDescription description) {
    description.meshes.push_back(bench::displaced_sphere(bench::benchmark_sphere(100, 50), 0));
    return build_scene(description);
}

// FNV-1a over the bytes of what a workload computed: printed as "checksum HEX" and compared by
// perf_gate.sh with the baseline and across ISAs, so a kernel that skips work (and so counts
// fewer instructions) fails the gate instead of passing as faster.
struct Checksum {
    uint64_t h = 1469598103934665603ull;
    template <typename T>
    void add(const T& value) {
        unsigned char bytes[sizeof(T)];
        std::memcpy(bytes, &value, sizeof(T));
        for (unsigned char b : bytes) h = (h ^ b) * 1099511628211ull;
    }
    void print() const { std::printf("checksum %016llx\n", static_cast<unsigned long long>(h)); }
};

}  // namespace

int main(int argc, char** argv) {
    if (argc < 3) return usage();
    const std::string scene_path = argv[1], what = argv[2];
    if (what == "build" && argc == 3) {
        const Scene scene = meshed_scene(load_scene_file(scene_path));
        CALLGRIND_TOGGLE_COLLECT;
        const Bvh bvh = build_bvh(scene, {8, 8, 1});
        CALLGRIND_TOGGLE_COLLECT;
        std::printf("nodes %zu\n", bvh.stats().node_count);
        Checksum sum;
        sum.add(bvh.stats().node_count), sum.add(bvh.stats().leaf_count), sum.add(bvh.stats().sah_cost);
        sum.print();
        return 0;
    }
    if (argc < 4) return usage();
    const auto isa = parse_isa(argv[3]);
    if (!isa || !cpu_supports(*isa)) {
        std::fprintf(stderr, "perf_gate_workload: ISA '%s' unknown or not supported here\n", argv[3]);
        return 2;
    }
    SceneDescription description = load_scene_file(scene_path);

    if (what == "render" && (argc == 4 || argc == 5)) {
        description.settings.width = description.settings.height = 24;
        description.settings.spp = 2;
        const Scene scene = build_scene(description);
        RenderOptions options;
        if (argc == 5) options.aovs = parse_aov_list(argv[4]);
        Film film(24, 24, render_film_channels(scene, options.aovs));
        options.threads = 1;
        options.isa = *isa;
        CALLGRIND_TOGGLE_COLLECT;
        render(scene, options, film);
        CALLGRIND_TOGGLE_COLLECT;
        Checksum sum;
        for (const float value : film.resolve()) sum.add(value);
        sum.print();
        return 0;
    }
    if (what == "lightstart" && argc == 4) {
        const Scene scene = build_scene(description);
        const LightPathTracer tracer(scene, nullptr);
        constexpr uint32_t kPaths = 20000;
        LightPointQueue points;
        points.reserve(kPaths);
        for (uint32_t index = 0; index < kPaths; ++index) {
            const AreaLightStart s = tracer.area_light_start(light_path_key(0, index, 0));
            points.push(s.light.position, s.light.error, s.light.normal, s.direction.first, s.direction.second, index);
        }
        ShadowQueue rays;
        rays.reserve(kPaths);
        const ShadeKernels& k = shade_kernels(*isa);
        CALLGRIND_TOGGLE_COLLECT;
        k.aim_area_light_rays(points, rays);
        CALLGRIND_TOGGLE_COLLECT;
        std::printf("rays %zu\n", rays.count);
        Checksum sum;
        for (std::size_t i = 0; i < rays.count; ++i) {
            sum.add(rays.path[i]), sum.add(rays.ox[i]), sum.add(rays.oy[i]), sum.add(rays.oz[i]);
            sum.add(rays.dx[i]), sum.add(rays.dy[i]), sum.add(rays.dz[i]);
        }
        sum.print();
        return 0;
    }
    if (what == "specular" && argc == 4) {
        const Scene scene = build_scene(description);
        const LightPathTracer tracer(scene, nullptr);
        constexpr uint32_t kVertex = 4;  // past rr_start_bounce: the roulette runs
        SpecularVertexQueue queue;
        queue.reserve(40000);
        for (uint32_t index = 0; index < 40000; ++index) {
            const uint64_t key = light_path_key(0, index, 0);
            const auto r = tracer.start(key);
            if (!r) continue;
            const Hit hit = intersect_closest(scene, r->ray);
            if (hit.found()) tracer.queue_specular(key, kVertex, *r, surface_at(scene, r->ray, hit), index, queue);
        }
        RayQueue next;
        next.reserve(queue.count);
        const ShadeKernels& k = shade_kernels(*isa);
        CALLGRIND_TOGGLE_COLLECT;
        k.continue_specular(queue, tracer.roulette_at(kVertex), scene.settings.accuracy.fresnel, next);
        CALLGRIND_TOGGLE_COLLECT;
        std::printf("vertices %zu, continued %zu\n", queue.count, next.count);
        Checksum sum;
        for (std::size_t i = 0; i < next.count; ++i) {
            sum.add(next.path[i]), sum.add(next.ox[i]), sum.add(next.oy[i]), sum.add(next.oz[i]);
            sum.add(next.dx[i]), sum.add(next.dy[i]), sum.add(next.dz[i]);
            sum.add(next.throughput_r[i]), sum.add(next.throughput_g[i]), sum.add(next.throughput_b[i]);
        }
        sum.print();
        return 0;
    }
    const bool smooth = argc == 5 && std::string(argv[4]) == "smooth";
    if (what == "shade" && (argc == 4 || smooth)) {
        // smooth: the BVH cases' scene, whose sphere has vertex normals, found through its tree.
        const Scene scene = smooth ? meshed_scene(description) : build_scene(description);
        const Rays rays = incoherent_rays(20000);
        const std::size_t n = rays.ox.size();
        std::vector<float> t(n), u(n), v(n);
        std::vector<uint32_t> prim(n);
        const HitView found{t.data(), u.data(), v.data(), prim.data()};
        if (smooth) {
            const Bvh bvh = build_bvh(scene, {8, 8, 1});
            intersect_kernels(Isa::scalar).closest_bvh(bvh_view(bvh), rays.view(), found);
        } else {
            intersect_kernels(Isa::scalar).closest_raypacket(FlatScene(scene).view(), rays.view(), found);
        }
        DiffuseVertexQueue queue;
        queue.reserve(n, 1);
        constexpr uint32_t kBounce = 3;  // past rr_start_bounce: the roulette runs
        for (std::size_t i = 0; i < n; ++i) {
            if (prim[i] == kNoHit) continue;
            const Ray ray{{rays.ox[i], rays.oy[i], rays.oz[i]}, {rays.dx[i], rays.dy[i], rays.dz[i]}};
            const SurfacePoint surface = surface_at(scene, ray, {t[i], prim[i], u[i], v[i]});
            const Material& m = scene.materials[surface.material];
            if (!continues_as_diffuse(m)) continue;
            const PathSeed path{path_key(0, uint32_t(i), 0), 0};
            const DefaultEstimator::Sampler random(path, kBounce, 1);
            const ContinuationRandom draws = continuation_random<DefaultEstimator>(random);
            const bool samples_lights = gathers_direct_light(m);
            queue.push(surface, m, ray.direction, glm::vec3(0.8f, 0.5f, 0.3f), draws.direction.first, draws.direction.second,
                       draws.choice_and_roulette.second, uint32_t(i), false, samples_lights);
            if (samples_lights) queue.set_light_sample(queue.count - 1, 0, light_sample_point<DefaultEstimator>(scene, random, 0));
        }
        RayQueue next, queued_rays;
        next.reserve(queue.count);
        queued_rays.reserve(n);
        HitQueue queued_hits;
        queued_hits.reserve(n);
        for (std::size_t i = 0; i < n; ++i) {
            queued_rays.push({{rays.ox[i], rays.oy[i], rays.oz[i]}, {rays.dx[i], rays.dy[i], rays.dz[i]}}, glm::vec3(1.0f), 0, 0);
            queued_hits.set(i, {t[i], prim[i], u[i], v[i]});
        }
        ShadowQueue shadows;
        shadows.reserve(queue.count);
        SurfaceChunk surfaces;
        Checksum sum;
        const ShadeKernels& k = shade_kernels(*isa);
        CALLGRIND_TOGGLE_COLLECT;
        for (std::size_t first = 0; first < n; first += SurfaceChunk::kSize) {
            const std::size_t count = std::min(SurfaceChunk::kSize, n - first);
            k.surface_points(scene, queued_rays, queued_hits, first, count, surfaces);
            CALLGRIND_TOGGLE_COLLECT;
            for (std::size_t i = 0; i < count; ++i)
                if (prim[first + i] != kNoHit) {
                    sum.add(surfaces.px[i]), sum.add(surfaces.ny[i]), sum.add(surfaces.material[i]);
                    if (smooth) sum.add(surfaces.sny[i]), sum.add(surfaces.smooth[i]);
                }
            CALLGRIND_TOGGLE_COLLECT;
        }
        k.sample_diffuse_lights(queue, {1, false, std::numeric_limits<float>::infinity()}, shadows);
        k.continue_diffuse(queue, {true, false, false}, next);
        CALLGRIND_TOGGLE_COLLECT;
        const std::size_t smooth_vertices =
            std::count_if(queue.flags.begin(), queue.flags.begin() + queue.count, [](uint8_t f) { return f & DiffuseVertexQueue::kSmooth; });
        std::printf("vertices %zu (smooth %zu), shadow rays %zu, continued %zu\n", queue.count, smooth_vertices, shadows.count,
                    next.count);
        for (std::size_t i = 0; i < next.count; ++i) {
            sum.add(next.path[i]), sum.add(next.ox[i]), sum.add(next.oy[i]), sum.add(next.oz[i]);
            sum.add(next.dx[i]), sum.add(next.dy[i]), sum.add(next.dz[i]);
            sum.add(next.throughput_r[i]), sum.add(next.throughput_g[i]), sum.add(next.throughput_b[i]);
        }
        for (std::size_t i = 0; i < shadows.count; ++i) {
            sum.add(shadows.path[i]), sum.add(shadows.dx[i]), sum.add(shadows.dy[i]), sum.add(shadows.dz[i]), sum.add(shadows.tmax[i]);
            sum.add(shadows.contribution_r[i]), sum.add(shadows.contribution_g[i]), sum.add(shadows.contribution_b[i]);
        }
        sum.print();
        return 0;
    }
    if (what != "intersect" || argc != 6) return usage();
    const std::string layout = argv[4], query = argv[5];
    const bool packets = layout == "bvhpackets";
    const bool bvh_layout = layout == "bvh" || packets || layout == "bvhinterleaved";
    const Scene scene = bvh_layout ? meshed_scene(description) : build_scene(description);
    const FlatScene flat_scene(scene);
    const SceneView view = flat_scene.view();
    const Bvh bvh = bvh_layout ? build_bvh(scene, {8, 8, 1}) : Bvh();
    BvhView tree = bvh_view(bvh);
    tree.prefetch_pushed = layout == "bvhinterleaved";  // the walks of a tree past the caches, on this one
    const IntersectKernels& k = intersect_kernels(*isa);
    const Rays rays = incoherent_rays(20000);
    const std::size_t n = rays.ox.size();
    std::vector<float> t(n), u(n), v(n);
    std::vector<uint32_t> prim(n);
    std::vector<uint8_t> occluded(n);
    const HitView hits{t.data(), u.data(), v.data(), prim.data()};
    const bool raypacket = layout == "raypacket";
    if (!raypacket && !bvh_layout && layout != "primpacket") return usage();
    if (query != "closest" && query != "any") return usage();

    CALLGRIND_TOGGLE_COLLECT;
    if (bvh_layout && query == "closest") (packets ? k.closest_bvh_packets : k.closest_bvh)(tree, rays.view(), hits);
    else if (bvh_layout) (packets ? k.any_bvh_packets : k.any_bvh)(tree, rays.view(), occluded.data());
    else if (query == "closest") (raypacket ? k.closest_raypacket : k.closest_primpacket)(view, rays.view(), hits);
    else (raypacket ? k.any_raypacket : k.any_primpacket)(view, rays.view(), occluded.data());
    CALLGRIND_TOGGLE_COLLECT;

    // A checksum, so the work cannot be optimised away and a broken kernel shows.
    std::size_t hit_count = 0;
    for (std::size_t i = 0; i < n; ++i) hit_count += query == "closest" ? prim[i] != kNoHit : occluded[i];
    std::printf("hits %zu\n", hit_count);
    Checksum sum;
    for (std::size_t i = 0; i < n; ++i) {
        if (query == "closest") sum.add(prim[i]), sum.add(prim[i] == kNoHit ? 0.0f : t[i]);
        else sum.add(occluded[i]);
    }
    sum.print();
    return 0;
}
