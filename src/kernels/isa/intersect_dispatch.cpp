#include "kernels/isa/intersect_dispatch.h"

#include <stdexcept>
#include <string>

namespace wt {

// __builtin_cpu_supports also checks that the OS saves the wide registers (XCR0), so a
// kernel it allows cannot fault on a kernel that disabled AVX-512 state. A sanitizer build made
// on a CPU without AVX-512 has no AVX-512 kernels (WT_WITHOUT_AVX512_KERNELS, CMakeLists.txt):
// for it no CPU supports them.
bool cpu_supports(Isa isa) {
    __builtin_cpu_init();
    switch (isa) {
        case Isa::scalar: return true;
        case Isa::sse4: return __builtin_cpu_supports("sse4.2");
        case Isa::avx2: return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
        case Isa::avx512:
#ifdef WT_WITHOUT_AVX512_KERNELS
            return false;
#endif
            return __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq") &&
                   __builtin_cpu_supports("avx512bw") && __builtin_cpu_supports("avx512vl");
    }
    return false;
}

Isa best_supported_isa() {
    for (Isa isa : {Isa::avx512, Isa::avx2, Isa::sse4})
        if (cpu_supports(isa)) return isa;
    return Isa::scalar;
}

namespace {
int kernel_variant(const AccuracySettings& a) {
    return 2 * (a.triangles == TriangleTest::watertight) + (a.spheres == SphereTest::cancellation_free);
}
}  // namespace

const IntersectKernels& intersect_kernels(Isa isa, const AccuracySettings& accuracy) {
    if (!cpu_supports(isa)) throw std::runtime_error(std::string("this CPU does not support the ") + isa_name(isa) + " kernels");
    const int variant = kernel_variant(accuracy);
    switch (isa) {
        case Isa::sse4: return kIntersectSse4[variant];
        case Isa::avx2: return kIntersectAvx2[variant];
        case Isa::avx512:
#ifdef WT_WITHOUT_AVX512_KERNELS
            break;  // not reached: cpu_supports() said no
#else
            return kIntersectAvx512[variant];
#endif
        case Isa::scalar: break;
    }
    return kIntersectScalar[variant];
}

namespace {
const TriangleSoA& served_triangles(const Scene& scene) {
    if (!scene.triangles.serves(scene.settings.accuracy.triangles))
        throw std::invalid_argument(std::string("intersect: the scene's triangles were stored for another triangle test than ") +
                                    name_of(scene.settings.accuracy.triangles) +
                                    "; build the scene with the accuracy settings it is rendered with");
    return scene.triangles;
}
}  // namespace

FlatScene::FlatScene(const Scene& scene) : triangles_(triangle_rows(served_triangles(scene))), spheres_(&scene.spheres) {}

SceneView FlatScene::view() const {
    const SphereSoA& s = *spheres_;
    SceneView v;
    v.triangles = triangle_view(triangles_);
    v.spheres = {s.cx.data(), s.cy.data(), s.cz.data(), s.radius.data(), uint32_t(s.size()), triangles_.count};
    return v;
}

RayView ray_view(const RayQueue& r) {
    return {r.ox.data(), r.oy.data(), r.oz.data(), r.dx.data(), r.dy.data(), r.dz.data(), nullptr, uint32_t(r.count)};
}

HitView hit_view(HitQueue& h) { return {h.t.data(), h.u.data(), h.v.data(), h.prim.data()}; }

RayView ray_view(const ShadowQueue& s) {
    return {s.ox.data(), s.oy.data(), s.oz.data(), s.dx.data(), s.dy.data(), s.dz.data(), s.tmax.data(), uint32_t(s.count)};
}

}  // namespace wt
