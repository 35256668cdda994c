#include "kernels/accel/bvh_primitives.h"

namespace wt {

void BvhPrimitives::append(const Scene& scene, uint32_t id) {
    const TriangleSoA& t = scene.triangles;
    if (id < t.size()) {
        v0x.push_back(t.v0x[id]), v0y.push_back(t.v0y[id]), v0z.push_back(t.v0z[id]);
        if (test == TriangleTest::watertight) {
            v1x.push_back(t.v1x[id]), v1y.push_back(t.v1y[id]), v1z.push_back(t.v1z[id]);
            v2x.push_back(t.v2x[id]), v2y.push_back(t.v2y[id]), v2z.push_back(t.v2z[id]);
        } else {
            e1x.push_back(t.e1x[id]), e1y.push_back(t.e1y[id]), e1z.push_back(t.e1z[id]);
            e2x.push_back(t.e2x[id]), e2y.push_back(t.e2y[id]), e2z.push_back(t.e2z[id]);
            nx.push_back(t.scaled_nx[id]), ny.push_back(t.scaled_ny[id]), nz.push_back(t.scaled_nz[id]);
        }
        planar_prim.push_back(id);
        return;
    }
    const SphereSoA& s = scene.spheres;
    const std::size_t i = id - t.size();
    cx.push_back(s.cx[i]), cy.push_back(s.cy[i]), cz.push_back(s.cz[i]), radius.push_back(s.radius[i]);
    sphere_prim.push_back(id);
}

std::size_t BvhPrimitives::bytes() const {
    std::size_t floats = 0;
    for (const auto* a : {&v0x, &v0y, &v0z, &e1x, &e1y, &e1z, &e2x, &e2y, &e2z, &nx, &ny, &nz, &v1x, &v1y, &v1z, &v2x,
                          &v2y, &v2z, &cx, &cy, &cz, &radius})
        floats += a->size();
    return floats * sizeof(float) + (planar_prim.size() + sphere_prim.size()) * sizeof(uint32_t);
}

TriangleView BvhPrimitives::planar_view() const {
    return {v0x.data(), v0y.data(), v0z.data(), e1x.data(), e1y.data(), e1z.data(), e2x.data(), e2y.data(),
            e2z.data(), nx.data(),  ny.data(),  nz.data(),  v1x.data(), v1y.data(), v1z.data(), v2x.data(),
            v2y.data(), v2z.data(), planar_count(), 0u};
}

SphereView BvhPrimitives::sphere_view() const { return {cx.data(), cy.data(), cz.data(), radius.data(), sphere_count(), 0u}; }

}  // namespace wt
