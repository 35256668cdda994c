#pragma once
// What the kernel tests share: rays in the SoA layout the kernels read, and every accuracy
// combination the kernels are compiled for.

#include <algorithm>
#include <cstdint>
#include <limits>
#include <vector>

#include "core/base/accuracy.h"
#include "core/base/ray.h"
#include "kernels/primitives/soa_views.h"

namespace wt::test {

struct RayBatch {
    std::vector<float> ox, oy, oz, dx, dy, dz, tmax;
    void push(const Ray& r, float t = std::numeric_limits<float>::infinity()) {
        ox.push_back(r.origin.x), oy.push_back(r.origin.y), oz.push_back(r.origin.z);
        dx.push_back(r.direction.x), dy.push_back(r.direction.y), dz.push_back(r.direction.z);
        tmax.push_back(t);
    }
    std::size_t size() const { return ox.size(); }
    Ray ray(std::size_t i) const { return {{ox[i], oy[i], oz[i]}, {dx[i], dy[i], dz[i]}}; }
    // Rays [first, first + count); with_tmax false: every ray unbounded.
    RayView view(bool with_tmax, std::size_t first = 0, std::size_t count = SIZE_MAX) const {
        count = std::min(count, ox.size() - first);
        return {ox.data() + first, oy.data() + first, oz.data() + first, dx.data() + first, dy.data() + first,
                dz.data() + first, with_tmax ? tmax.data() + first : nullptr, uint32_t(count)};
    }
};

// Moller-Trumbore or watertight triangles, quadratic or cancellation-free spheres.
inline std::vector<AccuracySettings> accuracy_variants() {
    std::vector<AccuracySettings> all;
    for (TriangleTest t : {TriangleTest::moller_trumbore, TriangleTest::watertight})
        for (SphereTest s : {SphereTest::quadratic, SphereTest::cancellation_free}) all.push_back({t, s, FresnelModel::schlick});
    return all;
}

}  // namespace wt::test
