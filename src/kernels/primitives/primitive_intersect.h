#pragma once
// One ray against one primitive, scalar. These are the width-1 versions the SIMD kernels are
// checked against. Every rejection is written as !(inside) so that a NaN — from a parallel ray
// (det = 0) or a degenerate triangle — rejects the hit instead of accepting it.

#include <cmath>
#include <utility>

#include <glm/geometric.hpp>

#include "core/geometry/geometry_soa.h"
#include "core/base/ray.h"

namespace wt {

// Moller & Trumbore 1997, two-sided, rearranged with the scalar triple product (as Embree's
// Moller-Trumbore intersector is) so that the triangle's scaled normal n = cross(e1, e2) is
// read instead of recomputed. With c = v0 - o and r = cross(c, d):
//     den = d.n,   u = (e2.r) / den,   v = -(e1.r) / den,   t = (c.n) / den.
// That is 18 multiplications per ray and triangle where the textbook order takes 27, and the
// SIMD kernels are bound by multiplications. den's sign is moved onto the numerators (exact),
// so the inside tests compare numerators with |den| and u, v are divided out only for a hit
// that is kept; primitives/triangle_lanes.h does the same arithmetic in the same order, so every
// kernel returns these bits. A parallelogram entry (see TriangleSoA) differs only in its
// inside test: u <= 1 and v <= 1 instead of u + v <= 1.
inline bool intersect_triangle(const TriangleSoA& tris, uint32_t i, const Ray& ray, Hit& hit) {
    const glm::vec3 n = tris.scaled_normal(i);
    const float den = glm::dot(ray.direction, n);
    if (den == 0.0f) return false;  // ray parallel to the plane, or a degenerate triangle
    const bool flip = den < 0.0f;
    const float abs_den = std::fabs(den);
    const glm::vec3 c = tris.vertex0(i) - ray.origin;
    const glm::vec3 r = glm::cross(c, ray.direction);
    const float u_num = flip ? -glm::dot(tris.edge2(i), r) : glm::dot(tris.edge2(i), r);
    const float v_num = -(flip ? -glm::dot(tris.edge1(i), r) : glm::dot(tris.edge1(i), r));
    const bool below_far_edges = tris.is_parallelogram(i) ? u_num <= abs_den && v_num <= abs_den : u_num + v_num <= abs_den;
    if (!(u_num >= 0.0f && v_num >= 0.0f && below_far_edges)) return false;
    const float t = glm::dot(c, n) / den;
    if (!(t > 0.0f && t < hit.t)) return false;
    hit.t = t;
    hit.prim = i;
    hit.u = u_num / abs_den;
    hit.v = v_num / abs_den;
    return true;
}

// Watertight ray-triangle test, Woop, Benthin & Wald, "Watertight Ray/Triangle Intersection"
// (JCGT 2013). The ray is sheared so it points along +z from the origin; the test is then 2D
// edge functions of the translated vertices, evaluated identically for the two triangles that
// share an edge, so a ray on the edge hits at least one of them. An edge function that comes
// out exactly 0 is recomputed in double: in float its sign is not trustworthy. Triangles only:
// a scene built for this test has no parallelograms (build_scene splits its quads).
struct WatertightRay {
    int kx, ky, kz;        // axis permutation: kz is the dominant direction axis
    float sx, sy, sz;      // shear constants
};

inline WatertightRay watertight_ray(const glm::vec3& d) {
    WatertightRay w;
    const glm::vec3 a = glm::abs(d);
    w.kz = a.x > a.y ? (a.x > a.z ? 0 : 2) : (a.y > a.z ? 1 : 2);
    w.kx = w.kz == 2 ? 0 : w.kz + 1;
    w.ky = w.kx == 2 ? 0 : w.kx + 1;
    if (d[w.kz] < 0.0f) std::swap(w.kx, w.ky);  // keep the winding, so the sign test stays valid
    w.sx = d[w.kx] / d[w.kz];
    w.sy = d[w.ky] / d[w.kz];
    w.sz = 1.0f / d[w.kz];
    return w;
}

// The 2D edge function of sheared vertices p and q, with the double-precision retry at zero.
inline float edge_function(float px, float py, float qx, float qy) {
    const float e = px * qy - py * qx;
    if (e != 0.0f) return e;
    return float(double(px) * double(qy) - double(py) * double(qx));
}

inline bool intersect_triangle_watertight(const TriangleSoA& tris, uint32_t i, const Ray& ray, const WatertightRay& w,
                                          Hit& hit) {
    const glm::vec3 a = tris.vertex0(i) - ray.origin;
    const glm::vec3 b = tris.vertex1(i) - ray.origin;
    const glm::vec3 c = tris.vertex2(i) - ray.origin;
    const float ax = a[w.kx] - w.sx * a[w.kz], ay = a[w.ky] - w.sy * a[w.kz];
    const float bx = b[w.kx] - w.sx * b[w.kz], by = b[w.ky] - w.sy * b[w.kz];
    const float cx = c[w.kx] - w.sx * c[w.kz], cy = c[w.ky] - w.sy * c[w.kz];
    const float u = edge_function(cx, cy, bx, by);  // weight of v0
    const float v = edge_function(ax, ay, cx, cy);  // weight of v1
    const float e = edge_function(bx, by, ax, ay);  // weight of v2
    if ((u < 0.0f || v < 0.0f || e < 0.0f) && (u > 0.0f || v > 0.0f || e > 0.0f)) return false;
    const float det = u + v + e;
    if (det == 0.0f) return false;
    const float scaled_t = u * (w.sz * a[w.kz]) + v * (w.sz * b[w.kz]) + e * (w.sz * c[w.kz]);
    // Divided, not multiplied by 1/det: the SIMD kernels divide u and v only for the hit they
    // keep, and must get these bits.
    const float t = scaled_t / det;
    if (!(t > 0.0f && t < hit.t)) return false;
    hit.t = t;
    hit.prim = i;
    hit.u = v / det;
    hit.v = e / det;
    return true;
}

// The textbook quadratic for a unit-length direction: t = -b -+ sqrt(b^2 - c), with
// b = dot(o - c, d) and c = |o - c|^2 - r^2. The far root serves rays that start inside
// (refracted rays in glass). prim_id is the sphere's id in the shared primitive index space.
inline bool intersect_sphere(const SphereSoA& spheres, uint32_t i, uint32_t prim_id, const Ray& ray, Hit& hit) {
    const glm::vec3 oc = ray.origin - spheres.center(i);
    const float r = spheres.radius[i];
    const float b = glm::dot(oc, ray.direction);
    const float c = glm::dot(oc, oc) - r * r;
    const float discriminant = b * b - c;
    if (!(discriminant >= 0.0f)) return false;
    const float root = std::sqrt(discriminant);
    const float near_t = -b - root;
    const float t = near_t > 0.0f ? near_t : -b + root;
    if (!(t > 0.0f && t < hit.t)) return false;
    hit.t = t;
    hit.prim = prim_id;
    hit.u = hit.v = 0.0f;
    return true;
}

// Ray Tracing Gems ch. 7 (Haines et al., "Precision Improvements for Ray/Sphere Intersection"):
// the discriminant r^2 - |f - (f.d) d|^2 comes from the closest-approach vector instead of
// b^2 - c, which cancels catastrophically for small or distant spheres; the roots come from
// q = -b - sign(b) sqrt(disc) as q and c / q, so neither subtracts nearly equal numbers.
inline bool intersect_sphere_cancellation_free(const SphereSoA& spheres, uint32_t i, uint32_t prim_id, const Ray& ray,
                                               Hit& hit) {
    const glm::vec3 f = ray.origin - spheres.center(i);
    const float r = spheres.radius[i];
    const float b = glm::dot(f, ray.direction);
    const glm::vec3 closest = f - b * ray.direction;
    const float discriminant = r * r - glm::dot(closest, closest);
    if (!(discriminant >= 0.0f)) return false;
    const float c = glm::dot(f, f) - r * r;
    const float q = -b - std::copysign(std::sqrt(discriminant), b);
    const float t0 = c / q, t1 = q;
    const float near_t = t0 < t1 ? t0 : t1;
    const float far_t = t0 < t1 ? t1 : t0;
    const float t = near_t > 0.0f ? near_t : far_t;
    if (!(t > 0.0f && t < hit.t)) return false;
    hit.t = t;
    hit.prim = prim_id;
    hit.u = hit.v = 0.0f;
    return true;
}

}  // namespace wt
