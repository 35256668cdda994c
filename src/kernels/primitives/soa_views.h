#pragma once
// Plain pointer views of the SoA buffers, the only scene and queue types the per-ISA kernel
// translation units see. They hold no inline functions and pull in no STL or GLM: any inline
// function compiled into an -mavx512f translation unit could be the copy the linker keeps for
// the whole program, and would then crash a CPU without AVX-512 (see simd/isa.h).

#include <cstdint>

namespace wt {

struct TriangleView {
    const float *v0x, *v0y, *v0z;
    const float *e1x, *e1y, *e1z;  // Moller-Trumbore reads the edges and the scaled normal
    const float *e2x, *e2y, *e2z;
    const float *nx, *ny, *nz;     // cross(e1, e2), unnormalized
    const float *v1x, *v1y, *v1z;  // the watertight test reads the vertices
    const float *v2x, *v2y, *v2z;
    uint32_t count;
    uint32_t parallelogram_count;  // entries [0, parallelogram_count) are parallelograms (Moller-Trumbore only)
};

struct SphereView {
    const float *cx, *cy, *cz, *radius;
    uint32_t count;
    uint32_t first_prim;  // id of sphere 0 in the shared primitive index space (= triangle count)
};

struct SceneView {
    TriangleView triangles;
    SphereView spheres;
};

struct RayView {
    const float *ox, *oy, *oz;
    const float *dx, *dy, *dz;  // unit length
    const float* tmax;          // per ray; nullptr means +infinity
    uint32_t count;
};

// Closest-hit results; prim is UINT32_MAX (kNoHit) for a miss, t is then +infinity.
struct HitView {
    float *t, *u, *v;
    uint32_t* prim;
};

}  // namespace wt
