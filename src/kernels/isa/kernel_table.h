#pragma once
// The table of intersection kernels one ISA's translation unit exports: every query, layout and
// accuracy combination, instantiated from the generic loops at this ISA's widest vector.

#include "core/base/accuracy.h"
#include "kernels/accel/brute_force.h"
#include "kernels/accel/bvh_packet_traverse.h"
#include "kernels/accel/bvh_traverse.h"
#include "kernels/accel/scene_bvh_query.h"
#include "kernels/isa/intersect_kernels.h"

namespace wt::packet {
inline namespace WT_SIMD_ISA {

template <TriangleTest T, SphereTest S, int N>
constexpr IntersectKernels make_kernels(Isa isa) {
    return {isa,
            N,
            &raypacket_brute_force<Query::closest, T, S, N>,
            &primpacket_brute_force<Query::closest, T, S, N>,
            &raypacket_brute_force<Query::any, T, S, N>,
            &primpacket_brute_force<Query::any, T, S, N>,
            &scene_bvh_query<Query::closest, T, S, N, false>,
            &scene_bvh_query<Query::any, T, S, N, false>,
            &scene_bvh_query<Query::closest, T, S, N, true>,
            &scene_bvh_query<Query::any, T, S, N, true>};
}

// One table entry per accuracy combination, in the order kernel_variant() indexes them:
// (Moller-Trumbore, quadratic), (MT, cancellation-free), (watertight, quadratic), (watertight, c.-f.).
template <int N>
struct KernelVariants {
    IntersectKernels variants[kKernelVariantCount];
};

template <int N>
constexpr KernelVariants<N> make_intersect_kernels(Isa isa) {
    return {{make_kernels<TriangleTest::moller_trumbore, SphereTest::quadratic, N>(isa),
             make_kernels<TriangleTest::moller_trumbore, SphereTest::cancellation_free, N>(isa),
             make_kernels<TriangleTest::watertight, SphereTest::quadratic, N>(isa),
             make_kernels<TriangleTest::watertight, SphereTest::cancellation_free, N>(isa)}};
}

}  // namespace WT_SIMD_ISA
}  // namespace wt::packet
