#pragma once
// Axis-aligned boxes for the BVH builder, and how far to pad them so the traversal never
// rejects a box whose primitive the flat kernels would hit.
//
// The builder spends its time extending boxes, so a box is two SSE registers (lanes x, y, z;
// the fourth unused, and kept finite and normal: a denormal there would take a microcode assist
// in every subtraction and product, see PrimRef::lo_xyz). SSE2 is part of x86-64, so this code
// runs on every CPU the renderer does, and it is not one of the per-ISA kernels.

#include <emmintrin.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include <glm/vec3.hpp>

namespace wt {

struct Box {
    __m128 lo = _mm_set1_ps(std::numeric_limits<float>::infinity());
    __m128 hi = _mm_set1_ps(-std::numeric_limits<float>::infinity());

    static Box of(__m128 lo, __m128 hi) {
        Box b;
        b.lo = lo, b.hi = hi;
        return b;
    }
    void extend(const Box& b) { lo = _mm_min_ps(lo, b.lo), hi = _mm_max_ps(hi, b.hi); }
    void extend(__m128 p) { lo = _mm_min_ps(lo, p), hi = _mm_max_ps(hi, p); }
    void extend_point(const glm::vec3& p) { extend(_mm_setr_ps(p.x, p.y, p.z, 0.0f)); }

    float lo_at(int axis) const { return lane(lo, axis); }
    float hi_at(int axis) const { return lane(hi, axis); }
    bool empty() const { return !(lo_at(0) <= hi_at(0)); }
    // Half the surface area (the SAH only ever compares areas); 0 for an empty box.
    float half_area() const {
        const __m128 d = _mm_max_ps(_mm_sub_ps(hi, lo), _mm_setzero_ps());  // -inf extents of an empty box -> 0
        const __m128 rotated = _mm_shuffle_ps(d, d, _MM_SHUFFLE(3, 0, 2, 1));  // (y, z, x)
        const __m128 products = _mm_mul_ps(d, rotated);                       // (xy, yz, zx)
        return _mm_cvtss_f32(products) + _mm_cvtss_f32(_mm_shuffle_ps(products, products, 1)) +
               _mm_cvtss_f32(_mm_shuffle_ps(products, products, 2));
    }
    Box padded(float pad) const {
        const __m128 p = _mm_set1_ps(pad);
        return of(_mm_sub_ps(lo, p), _mm_add_ps(hi, p));
    }

private:
    static float lane(__m128 v, int i) {
        alignas(16) float f[4];
        _mm_store_ps(f, v);
        return f[i];
    }
};

// The primitive tests compute a hit from v0 - o and products of edges, each rounded: the point
// they accept can lie outside the primitive's exact box by a few units of rounding of the
// coordinates and distances involved, which are bounded by the scene's extent, its distance from
// the origin and the camera's. A box padded by 2^-18 of that (64 float steps of it, far more
// than the few the tests lose) contains every such point; without the pad, the BVH tests find
// hundreds of rays in a million that the flat kernels hit and the tree misses. The ray-box test
// itself is made conservative by Ize's factor in the traversal (bvh_traverse.h). The pad is a
// size, not an epsilon per box, so no box is padded by less than its coordinates can resolve.
inline float rounding_pad(const Box& scene, const glm::vec3& eye) {
    float magnitude = 0.0f;
    for (int a = 0; a < 3; ++a) {
        magnitude = std::max({magnitude, std::fabs(scene.lo_at(a)), std::fabs(scene.hi_at(a)), std::fabs(eye[a]),
                              scene.hi_at(a) - scene.lo_at(a)});
    }
    return magnitude * 0x1p-18f;
}

}  // namespace wt
