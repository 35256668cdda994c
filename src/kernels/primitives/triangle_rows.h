#pragma once
// The rows the flat intersect kernels load N triangles at a time from, one contiguous array per
// component: copied from a scene's indexed triangles (geometry_soa.h), only where a flat loop
// reads them (a scene rendered without its BVH, a BVH's parallelograms beside its tree), so a
// meshed scene traced through its BVH stores each triangle once in the scene and once in the
// leaves. And the kernels' view (soa_views.h) of them, out of line for soa_views.h's plain-struct
// rule.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/base/aligned_vector.h"
#include "core/geometry/geometry_soa.h"
#include "kernels/primitives/soa_views.h"

namespace wt {

struct TriangleRows {
    AlignedVector<float> v0x, v0y, v0z;
    AlignedVector<float> e1x, e1y, e1z;
    AlignedVector<float> e2x, e2y, e2z;
    AlignedVector<float> scaled_nx, scaled_ny, scaled_nz;  // empty unless the triangles serve Moller-Trumbore
    AlignedVector<float> v1x, v1y, v1z;                    // empty unless they serve the watertight test
    AlignedVector<float> v2x, v2y, v2z;
    uint32_t count = 0;
    uint32_t parallelogram_count = 0;
};

// The first `count` entries of `t` (count <= t.size(), std::logic_error otherwise), the rows its
// tests read: TriangleSoA's vertex0, edges, scaled normal and vertices, bit for bit.
TriangleRows triangle_rows(const TriangleSoA& t, std::size_t count);
inline TriangleRows triangle_rows(const TriangleSoA& t) { return triangle_rows(t, t.size()); }
// The rows of entries `entries` of `t`, in that order, which must keep the parallelograms first
// (std::logic_error otherwise, or for an entry past the end): a flat loop over a few of a
// scene's primitives (kernels/caustics/specular_targets.h).
TriangleRows triangle_rows(const TriangleSoA& t, const std::vector<uint32_t>& entries);

TriangleView triangle_view(const TriangleRows& t);

}  // namespace wt
