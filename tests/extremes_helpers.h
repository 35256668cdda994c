#pragma once
// Trustworthy at the extremes: the intersection kernels, the optics and the renderer's settings
// where naive floating-point code breaks. Rays parallel to a triangle and one ulp off it,
// degenerate triangles, signed zeros, spheres far away, tiny and huge, rays spawned from hits,
// index-matched glass and total internal reflection at the critical angle, Oren-Nayar at
// grazing view, radiance overflowing to infinity, and 1x1 images with idle threads.
//
// Every intersection check runs on every implementation: the scalar textbook functions of
// primitive_intersect.h, and each ISA's kernels this CPU runs (intersect_kernels(isa)) in both
// layouts (ray packet and primitive packet), closest hit and any hit. A failing check prints
// the implementation, the ray in hex floats (%a, exact and pasteable into C++) and what came out.
//
// Comments marked FOUND describe a bug these tests found and how it was fixed. Two sphere tests
// assert what the default quadratic sphere test gets wrong (its documented precision limit)
// and that the cancellation-free option gets it right.

//
// What the extremes_*_test.cpp files share: failure reporting, every implementation of the
// intersection queries, small scenes.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <glm/ext/vector_double3.hpp>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "core/materials/bsdf.h"
#include "bsdf_helpers.h"
#include "core/materials/fresnel.h"
#include "core/path/path_vertex.h"
#include "core/base/ray_offset.h"
#include "core/sampling/sampling.h"
#include "kernels/isa/intersect_dispatch.h"
#include "kernels/primitives/primitive_intersect.h"
#include "kernels/accel/scene_intersect.h"
#include "render_helpers.h"
#include "statistics.h"
#include "test_scenes.h"

namespace wt::extremes {

using test::diffuse;
using test::direction_at;
using test::directional_albedo;

inline constexpr float kInf = std::numeric_limits<float>::infinity();
// The surface normal of the glass and Oren-Nayar checks.
inline const glm::vec3 kUp(0.0f, 0.0f, 1.0f);

// ---- reporting ------------------------------------------------------------------------------

inline std::string hex(double x) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%a", x);
    return buffer;
}
inline std::string hex(const glm::vec3& v) { return "(" + hex(v.x) + ", " + hex(v.y) + ", " + hex(v.z) + ")"; }
inline std::string describe(const Ray& r) { return "origin " + hex(r.origin) + " direction " + hex(r.direction); }

// Collects failures: the first few are reported in full, the rest only counted, so one broken
// case among 100k rays does not bury the log.
class Failures {
public:
    // WT_FAILURES_SHOWN=n in the environment shows n failures per check instead.
    explicit Failures(int printed = 8) : printed_(std::getenv("WT_FAILURES_SHOWN") ? std::atoi(std::getenv("WT_FAILURES_SHOWN")) : printed) {}
    Failures(const Failures&) = delete;
    ~Failures() {
        if (count_ > printed_) ADD_FAILURE() << count_ << " failures in all; the first " << printed_ << " are shown above";
    }
    void add(const std::string& message) {
        if (count_++ < printed_) ADD_FAILURE() << message;
    }
    int count() const { return count_; }

private:
    int printed_;
    int count_ = 0;
};

// ---- every implementation of the intersection queries ---------------------------------------

struct Query {
    Ray ray;
    float tmax = kInf;
};

// What one implementation answered for one query: the closest hit and the any-hit flag.
struct Answer {
    float t = kInf, u = 0.0f, v = 0.0f;
    uint32_t prim = kNoHit;
    bool occluded = false;
    bool found() const { return prim != kNoHit; }
};

inline std::string describe(const Answer& a) {
    return "prim " + (a.found() ? std::to_string(a.prim) : std::string("none")) + " t " + hex(a.t) + " (" +
           std::to_string(a.t) + ") u " + hex(a.u) + " v " + hex(a.v) + " occluded " + (a.occluded ? "yes" : "no");
}

struct ImplementationRun {
    std::string implementation;
    std::vector<Answer> answers;
};

inline std::vector<Isa> supported_isas() {
    std::vector<Isa> isas;
    for (Isa isa : kAllIsas)
        if (cpu_supports(isa)) isas.push_back(isa);
    return isas;
}

// The scalar functions of primitive_intersect.h, primitive by primitive in id order, as the
// reference integrator calls them (scene_intersect.h; with the default accuracy settings these
// are the textbook Moller-Trumbore and quadratic tests).
inline Answer scalar_answer(const Scene& scene, const Query& q) {
    Answer a;
    const Hit closest = intersect_closest(scene, q.ray, q.tmax);
    if (closest.found()) a.t = closest.t, a.u = closest.u, a.v = closest.v, a.prim = closest.prim;
    a.occluded = intersect_any(scene, q.ray, q.tmax);
    return a;
}

// Runs every query through every implementation. Output buffers start as NaN / a sentinel, so
// a kernel that forgets to write a lane is caught by the NaN checks.
inline std::vector<ImplementationRun> intersect_everywhere(const Scene& scene, const std::vector<Query>& queries) {
    std::vector<ImplementationRun> runs;
    ImplementationRun scalar{"scalar functions (primitive_intersect.h)", {}};
    for (const Query& q : queries) scalar.answers.push_back(scalar_answer(scene, q));
    runs.push_back(std::move(scalar));

    const std::size_t n = queries.size();
    std::vector<float> ox(n), oy(n), oz(n), dx(n), dy(n), dz(n), tmax(n);
    for (std::size_t i = 0; i < n; ++i) {
        const Ray& r = queries[i].ray;
        ox[i] = r.origin.x, oy[i] = r.origin.y, oz[i] = r.origin.z;
        dx[i] = r.direction.x, dy[i] = r.direction.y, dz[i] = r.direction.z;
        tmax[i] = queries[i].tmax;
    }
    const RayView rays{ox.data(), oy.data(), oz.data(), dx.data(), dy.data(), dz.data(), tmax.data(), uint32_t(n)};
    const FlatScene flat_scene(scene);
    const SceneView view = flat_scene.view();
    for (Isa isa : supported_isas()) {
        const IntersectKernels& k = intersect_kernels(isa, scene.settings.accuracy);
        struct Layout {
            const char* name;
            void (*closest)(const SceneView&, const RayView&, const HitView&);
            void (*any)(const SceneView&, const RayView&, uint8_t*);
        };
        for (const Layout& layout : {Layout{"raypacket", k.closest_raypacket, k.any_raypacket},
                                     Layout{"primpacket", k.closest_primpacket, k.any_primpacket}}) {
            const float nan = std::numeric_limits<float>::quiet_NaN();
            std::vector<float> t(n, nan), u(n, nan), v(n, nan);
            std::vector<uint32_t> prim(n, 0xdeadbeefu);
            std::vector<uint8_t> occluded(n, 7);
            layout.closest(view, rays, {t.data(), u.data(), v.data(), prim.data()});
            layout.any(view, rays, occluded.data());
            ImplementationRun run{std::string(isa_name(isa)) + "/" + layout.name, std::vector<Answer>(n)};
            for (std::size_t i = 0; i < n; ++i) {
                Answer& a = run.answers[i];
                a.t = t[i], a.u = u[i], a.v = v[i], a.prim = prim[i];
                a.occluded = occluded[i] != 0;
                if (occluded[i] > 1) a.t = nan;  // never written: reported by the sanity check
            }
            runs.push_back(std::move(run));
        }
    }
    return runs;
}

// What must hold for any answer to any query: no NaN, a miss is (+inf, no primitive), a hit is
// finite, in (0, tmax), with barycentrics inside, and the any-hit query agrees with the closest.
inline std::string sanity_problem(const Scene& scene, const Query& q, const Answer& a) {
    if (std::isnan(a.t) || std::isnan(a.u) || std::isnan(a.v)) return "NaN in the output";
    if (a.occluded != a.found()) return "any-hit and closest-hit disagree";
    if (!a.found()) return a.t == kInf ? "" : "a miss must report t = +inf";
    if (a.prim >= scene.primitive_count()) return "primitive id out of range";
    if (!(std::isfinite(a.t) && a.t > 0.0f && a.t < q.tmax)) return "hit distance not finite or outside (0, tmax)";
    if (!std::isfinite(a.u) || !std::isfinite(a.v)) return "barycentrics not finite";
    // u + v may exceed 1 by an ulp or two: u and v are two separate divisions. A
    // parallelogram's u and v are each in [0, 1], exactly (u_num <= den gives u_num / den <= 1).
    if (scene.triangles.is_parallelogram(a.prim) && !(a.u >= 0.0f && a.v >= 0.0f && a.u <= 1.0f && a.v <= 1.0f))
        return "barycentrics outside the parallelogram";
    if (a.prim < scene.triangles.size() && !scene.triangles.is_parallelogram(a.prim) &&
        !(a.u >= 0.0f && a.v >= 0.0f && a.u + a.v <= 1.0f + 0x1p-22f))
        return "barycentrics outside the triangle";
    return "";
}

// Runs the queries everywhere and applies the sanity check plus `check` (which returns an
// empty string when the answer is acceptable) to every answer.
inline void expect_everywhere(const Scene& scene, const std::vector<Query>& queries,
                       const std::function<std::string(std::size_t, const Query&, const Answer&)>& check,
                       Failures& failures) {
    ASSERT_FALSE(queries.empty());
    for (const ImplementationRun& run : intersect_everywhere(scene, queries)) {
        for (std::size_t i = 0; i < queries.size(); ++i) {
            const Answer& a = run.answers[i];
            std::string problem = sanity_problem(scene, queries[i], a);
            if (problem.empty()) problem = check(i, queries[i], a);
            if (problem.empty()) continue;
            failures.add(run.implementation + ": " + problem + "\n  query #" + std::to_string(i) + ": " +
                         describe(queries[i].ray) + " tmax " + hex(queries[i].tmax) + "\n  got " + describe(a));
        }
    }
}

inline void expect_everywhere(const Scene& scene, const std::vector<Query>& queries,
                       const std::function<std::string(std::size_t, const Query&, const Answer&)>& check) {
    Failures failures;
    expect_everywhere(scene, queries, check, failures);
}

inline Scene scene_of(const std::vector<std::array<glm::vec3, 3>>& triangles, const std::vector<std::pair<glm::vec3, float>>& spheres) {
    Scene scene;
    Material m;
    m.name = "white";
    m.albedo = glm::vec3(0.5f);
    scene.materials.push_back(m);
    for (const auto& t : triangles) scene.triangles.push_back(t[0], t[1], t[2], 0);
    for (const auto& s : spheres) scene.spheres.push_back(s.first, s.second, 0);
    return scene;
}

inline glm::vec3 random_unit(std::mt19937& rng) {
    std::normal_distribution<float> n;
    for (;;) {
        const glm::vec3 d(n(rng), n(rng), n(rng));
        const float l = glm::length(d);
        if (l > 1e-3f) return d / l;
    }
}


// The roots of |o + t d - c|^2 = r^2 in double, for the float ray exactly as given (its direction
// is unit length only to within an ulp; the roots take |d| into account).
struct SphereTruth {
    bool line_hits = false;
    double near_t = 0.0, far_t = 0.0;
    double closest_distance = 0.0;  // from the centre to the ray's line
};

inline SphereTruth sphere_truth(const Ray& ray, const glm::vec3& center, float radius) {
    const glm::dvec3 o(ray.origin), d(ray.direction), c(center);
    const glm::dvec3 f = o - c;
    const double a = glm::dot(d, d), b = glm::dot(f, d), r = radius;
    const glm::dvec3 closest = f - (b / a) * d;
    SphereTruth s;
    s.closest_distance = glm::length(closest);
    const double discriminant = (r - s.closest_distance) * (r + s.closest_distance);  // r^2 - |closest|^2
    if (discriminant < 0.0) return s;
    s.line_hits = true;
    const double q = -(b + std::copysign(std::sqrt(a * discriminant), b));
    const double c2 = glm::dot(f, f) - r * r;
    const double t0 = q / a, t1 = q != 0.0 ? c2 / q : 0.0;
    s.near_t = std::min(t0, t1);
    s.far_t = std::max(t0, t1);
    return s;
}

}  // namespace wt::extremes
