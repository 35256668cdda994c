#pragma once
// surface_at (core/scene/scene.h) for a chunk of hits, N at a time: on triangles, the point
// from the barycentrics, its error bound (with the watertight test's floor where the scene uses
// it), the unit normal of the edges' cross product and, in a scene with vertex normals, the
// shading normal blended from them (ShadingNormalTable::at, blend_normals); on spheres, the
// point projected back onto the sphere, its bound and the outward normal. Bit for bit the scalar
// code, in the way of diffuse_continuation.h (tests/shade_kernels_test.cpp). Lanes whose ray
// missed or hit an instance (surface_kernel_ids) are left unspecified.

#include <cstdint>

#include "core/base/ray_offset.h"
#include "core/scene/scene.h"
#include "kernels/queues/ray_queues.h"
#include "kernels/queues/surface_chunk.h"
#include "kernels/shading/lanes.h"

namespace wt::shading {
inline namespace WT_SIMD_ISA {

template <int N>
inline Lanes3<N> gather3(vbool<N> m, const AlignedVector<float>& x, const AlignedVector<float>& y, const AlignedVector<float>& z,
                         vint<N> index) {
    return {vfloat<N>::gather(m, x.data(), index), vfloat<N>::gather(m, y.data(), index), vfloat<N>::gather(m, z.data(), index)};
}

template <int N>
inline Lanes3<N> magnitude(const Lanes3<N>& v) {
    return {simd::abs(v.x), simd::abs(v.y), simd::abs(v.z)};
}

// ShadingNormalTable::at for the `triangle` lanes: the vertex normals gathered (a flat mesh's
// hold NaN), blended with the barycentrics' weights in blend_normals' order and divided by
// their length, or `geometric` where the blend cancels, is not finite or the mesh is flat.
template <int N>
inline Lanes3<N> blended_vertex_normal(const Scene& scene, vbool<N> triangle, vint<N> i0, vint<N> i1, vint<N> i2, vfloat<N> u,
                                       vfloat<N> v, const Lanes3<N>& geometric) {
    const float* normals = reinterpret_cast<const float*>(scene.shading_normals.per_vertex());
    const auto normal = [&](vint<N> vertex) {
        const vint<N> at = vertex * vint<N>(3);  // glm::vec3: three floats
        return Lanes3<N>{vfloat<N>::gather(triangle, normals, at), vfloat<N>::gather(triangle, normals + 1, at),
                         vfloat<N>::gather(triangle, normals + 2, at)};
    };
    const Lanes3<N> n0 = normal(i0), n1 = normal(i1), n2 = normal(i2);
    const vfloat<N> w = 1.0f - u - v;
    const Lanes3<N> blended{w * n0.x + u * n1.x + v * n2.x, w * n0.y + u * n1.y + v * n2.y, w * n0.z + u * n1.z + v * n2.z};
    const vfloat<N> length2 = dot(blended, blended);
    const vfloat<N> length = simd::sqrt(length2);
    // Below 1e-12 the direction is the rounding noise of the cancellation; infinity - infinity
    // is NaN, so the second test is !isfinite(length2); a flat mesh's NaN fails the first.
    const vbool<N> usable = (length2 > 1e-12f) & ((length2 - length2) == 0.0f);
    return select(usable, Lanes3<N>{blended.x / length, blended.y / length, blended.z / length}, geometric);
}

// The hit triangles' data a few vectors ahead of the arithmetic: the vertex indices two vectors
// ahead, and the vertices (and their normals) one vector ahead, whose indices were asked for the
// vector before. In a mesh past the caches every hit's triangle is a miss of its own (the
// intersection kernels read the leaf blocks, not these arrays), and the kernel's gathers wait on
// the indices and then on the vertices; asked for early, the misses of several vectors overlap.
// Only past kSurfacePrefetchBytes: in a scene whose triangles stay in the caches the prefetches
// are instructions for nothing.
constexpr std::size_t kSurfacePrefetchBytes = std::size_t(16) << 20;

class TriangleDataPrefetch {
public:
    TriangleDataPrefetch(const Scene& scene, const HitQueue& hits, std::size_t first, std::size_t count)
        : t_(scene.triangles),
          normals_(scene.shading_normals.empty() ? nullptr : scene.shading_normals.per_vertex()),
          prim_(hits.prim.data() + first),
          count_(count) {}

    // The bytes a hit's surface point reads from: per triangle its indices and material, per
    // vertex its position and normal.
    static bool past_the_caches(const Scene& scene) {
        const std::size_t bytes = scene.triangles.size() * 4 * sizeof(uint32_t) +
                                  scene.triangles.vertex_count() * 3 * sizeof(float) + scene.shading_normals.bytes();
        return bytes > kSurfacePrefetchBytes;
    }

    // Always inlined: a function of prefetches alone is "pure" to g++ 12, and a call to it whose
    // result is unused is dropped, prefetches and all.
    [[gnu::always_inline]] void indices(std::size_t k, std::size_t lanes) const {
        for (std::size_t j = k; j < k + lanes && j < count_; ++j)
            if (const uint32_t p = prim_[j]; p < t_.size())
                __builtin_prefetch(&t_.i0[p]), __builtin_prefetch(&t_.i1[p]), __builtin_prefetch(&t_.i2[p]),
                    __builtin_prefetch(&t_.material[p]);
    }
    [[gnu::always_inline]] void vertices(std::size_t k, std::size_t lanes) const {
        for (std::size_t j = k; j < k + lanes && j < count_; ++j)
            if (const uint32_t p = prim_[j]; p < t_.size())
                for (const uint32_t vertex : {t_.i0[p], t_.i1[p], t_.i2[p]}) {
                    __builtin_prefetch(&t_.px[vertex]), __builtin_prefetch(&t_.py[vertex]), __builtin_prefetch(&t_.pz[vertex]);
                    if (normals_) __builtin_prefetch(&normals_[vertex]);
                }
    }

private:
    const TriangleSoA& t_;
    const glm::vec3* normals_;
    const uint32_t* prim_;
    std::size_t count_;
};

// Hits [first, first + count) of the queue, count at most SurfaceChunk::kSize, into `out` from 0.
// kVertexNormals: the scene has a ShadingNormalTable, and the shading normals are computed too.
// kPrefetch: the triangles are past the caches (TriangleDataPrefetch).
template <int N, bool kVertexNormals, bool kPrefetch>
void surface_points_with(const Scene& scene, const RayQueue& rays, const HitQueue& hits, std::size_t first, std::size_t count,
                         SurfaceChunk& out) {
    const TriangleSoA& t = scene.triangles;
    const SphereSoA& s = scene.spheres;
    const vint<N> triangle_count(int32_t(t.size())), own_count(int32_t(surface_kernel_ids(scene)));
    const bool watertight = scene.settings.accuracy.triangles == TriangleTest::watertight;
    const TriangleDataPrefetch prefetch(scene, hits, first, count);
    if constexpr (kPrefetch) prefetch.indices(0, 2 * N), prefetch.vertices(0, N);
    for (std::size_t k = 0; k < count; k += N) {
        if constexpr (kPrefetch) prefetch.indices(k + 2 * N, N), prefetch.vertices(k + N, N);
        const std::size_t i = first + k;
        const int lanes = count - k < std::size_t(N) ? int(count - k) : N;
        const auto load = [&](const AlignedVector<float>& a) { return vfloat<N>::load_partial(a.data() + i, lanes, 0.0f); };
        const vint<N> prim = vint<N>::load_partial(reinterpret_cast<const int32_t*>(hits.prim.data() + i), lanes,
                                                   vint<N>(int32_t(kNoHit)));
        const vbool<N> found = prim != vint<N>(int32_t(kNoHit));
        const vbool<N> triangle = found & (prim < triangle_count);  // found ids are below 2^31
        const vbool<N> sphere = found & ~triangle & (prim < own_count);  // not an instance's

        // Triangles: v0 + u e1 + v e2 from the vertices, triangle_point_error, TriangleSoA::normal.
        const auto vertex = [&](const AlignedVector<uint32_t>& index) {
            return vint<N>::gather(triangle, reinterpret_cast<const int32_t*>(index.data()), prim);
        };
        const vint<N> i0 = vertex(t.i0), i1 = vertex(t.i1), i2 = vertex(t.i2);
        const auto corner = [&](vint<N> index) { return gather3<N>(triangle, t.px, t.py, t.pz, index); };
        const Lanes3<N> v0 = corner(i0), v1 = corner(i1), v2 = corner(i2);
        const Lanes3<N> e1{v1.x - v0.x, v1.y - v0.y, v1.z - v0.z}, e2{v2.x - v0.x, v2.y - v0.y, v2.z - v0.z};
        const vfloat<N> u = load(hits.u), v = load(hits.v);
        const Lanes3<N> ue1{u * e1.x, u * e1.y, u * e1.z}, ve2{v * e2.x, v * e2.y, v * e2.z};
        const Lanes3<N> triangle_position{v0.x + ue1.x + ve2.x, v0.y + ue1.y + ve2.y, v0.z + ue1.z + ve2.z};
        const Lanes3<N> a = magnitude(v0), b = magnitude(ue1), c = magnitude(ve2);
        constexpr float gamma7 = rounding_gamma(7);
        Lanes3<N> triangle_error{gamma7 * (a.x + b.x + c.x), gamma7 * (a.y + b.y + c.y), gamma7 * (a.z + b.z + c.z)};
        if (watertight) {  // with_watertight_floor
            const vfloat<N> larger_xy = simd::select(triangle_error.x > triangle_error.y, triangle_error.x, triangle_error.y);
            const vfloat<N> floor = 0.25f * simd::select(larger_xy > triangle_error.z, larger_xy, triangle_error.z);
            triangle_error = {simd::select(triangle_error.x > floor, triangle_error.x, floor),
                              simd::select(triangle_error.y > floor, triangle_error.y, floor),
                              simd::select(triangle_error.z > floor, triangle_error.z, floor)};
        }
        const Lanes3<N> cross{e1.y * e2.z - e2.y * e1.z, e1.z * e2.x - e2.z * e1.x, e1.x * e2.y - e2.x * e1.y};
        const vfloat<N> length = simd::sqrt(dot(cross, cross));
        const vbool<N> degenerate = ~(length > 0.0f);  // a sliver: normal 0
        const Lanes3<N> triangle_normal{simd::select(degenerate, vfloat<N>(0.0f), cross.x / length),
                                        simd::select(degenerate, vfloat<N>(0.0f), cross.y / length),
                                        simd::select(degenerate, vfloat<N>(0.0f), cross.z / length)};

        // Spheres: the outward normal at o + t d, the point c + r n, sphere_point_error.
        const vint<N> sphere_index = prim - triangle_count;
        const Lanes3<N> centre = gather3<N>(sphere, s.cx, s.cy, s.cz, sphere_index);
        const vfloat<N> radius = vfloat<N>::gather(sphere, s.radius.data(), sphere_index);
        const vfloat<N> distance = load(hits.t);
        const Lanes3<N> w{load(rays.ox) + distance * load(rays.dx) - centre.x, load(rays.oy) + distance * load(rays.dy) - centre.y,
                          load(rays.oz) + distance * load(rays.dz) - centre.z};
        const vfloat<N> inverse_length = 1.0f / simd::sqrt(dot(w, w));
        const Lanes3<N> sphere_normal{w.x * inverse_length, w.y * inverse_length, w.z * inverse_length};
        const Lanes3<N> radial{radius * sphere_normal.x, radius * sphere_normal.y, radius * sphere_normal.z};
        const Lanes3<N> sphere_position{centre.x + radial.x, centre.y + radial.y, centre.z + radial.z};
        const Lanes3<N> cm = magnitude(centre), rm = magnitude(radial);
        constexpr float gamma5 = rounding_gamma(5);
        const Lanes3<N> sphere_error{gamma5 * (cm.x + rm.x), gamma5 * (cm.y + rm.y), gamma5 * (cm.z + rm.z)};

        const auto store3 = [&](AlignedVector<float>& x, AlignedVector<float>& y, AlignedVector<float>& z, const Lanes3<N>& on_triangle,
                                const Lanes3<N>& on_sphere) {
            const Lanes3<N> chosen = select(triangle, on_triangle, on_sphere);
            vfloat<N>::store(x.data() + k, chosen.x), vfloat<N>::store(y.data() + k, chosen.y), vfloat<N>::store(z.data() + k, chosen.z);
        };
        store3(out.px, out.py, out.pz, triangle_position, sphere_position);
        store3(out.ex, out.ey, out.ez, triangle_error, sphere_error);
        store3(out.nx, out.ny, out.nz, triangle_normal, sphere_normal);
        if constexpr (kVertexNormals) {
            const Lanes3<N> shading = blended_vertex_normal<N>(scene, triangle, i0, i1, i2, u, v, triangle_normal);
            store3(out.snx, out.sny, out.snz, shading, sphere_normal);
            // SurfacePoint::smooth: shading_normal != normal, glm's test (any coordinate differs).
            const vbool<N> smooth =
                triangle & ((shading.x != triangle_normal.x) | (shading.y != triangle_normal.y) | (shading.z != triangle_normal.z));
            vint<N>::store(reinterpret_cast<int32_t*>(out.smooth.data() + k), simd::select(smooth, vint<N>(1), vint<N>(0)));
        }
        const vint<N> material =
            simd::select(triangle, vint<N>::gather(triangle, reinterpret_cast<const int32_t*>(t.material.data()), prim),
                         vint<N>::gather(sphere, reinterpret_cast<const int32_t*>(s.material.data()), sphere_index));
        vint<N>::store(reinterpret_cast<int32_t*>(out.material.data() + k), material);
    }
}

template <int N>
void surface_points(const Scene& scene, const RayQueue& rays, const HitQueue& hits, std::size_t first, std::size_t count,
                    SurfaceChunk& out) {
    out.shading_normals = !scene.shading_normals.empty();
    const bool prefetch = TriangleDataPrefetch::past_the_caches(scene);
    if (out.shading_normals && prefetch) surface_points_with<N, true, true>(scene, rays, hits, first, count, out);
    else if (out.shading_normals) surface_points_with<N, true, false>(scene, rays, hits, first, count, out);
    else if (prefetch) surface_points_with<N, false, true>(scene, rays, hits, first, count, out);
    else surface_points_with<N, false, false>(scene, rays, hits, first, count, out);
}

}  // namespace WT_SIMD_ISA
}  // namespace wt::shading
