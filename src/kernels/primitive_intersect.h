#pragma once
// One ray against one primitive, scalar. These are the width-1 versions the SIMD kernels are
// checked against. Every rejection is written as !(inside) so that a NaN — from a parallel ray
// (det = 0) or a degenerate triangle — rejects the hit instead of accepting it.

#include <cmath>

#include <glm/geometric.hpp>

#include "core/geometry_soa.h"
#include "core/ray.h"

namespace wt {

// Moller & Trumbore 1997, two-sided. On a hit closer than hit.t, updates hit and returns true.
inline bool intersect_triangle(const TriangleSoA& tris, uint32_t i, const Ray& ray, Hit& hit) {
    const glm::vec3 e1 = tris.edge1(i);
    const glm::vec3 e2 = tris.edge2(i);
    const glm::vec3 p = glm::cross(ray.direction, e2);
    const float det = glm::dot(e1, p);
    if (det == 0.0f) return false;  // ray parallel to the plane, or a degenerate triangle
    const float inv_det = 1.0f / det;
    const glm::vec3 s = ray.origin - tris.vertex0(i);
    const float u = glm::dot(s, p) * inv_det;
    if (!(u >= 0.0f && u <= 1.0f)) return false;
    const glm::vec3 q = glm::cross(s, e1);
    const float v = glm::dot(ray.direction, q) * inv_det;
    if (!(v >= 0.0f && u + v <= 1.0f)) return false;
    const float t = glm::dot(e2, q) * inv_det;
    if (!(t > 0.0f && t < hit.t)) return false;
    hit.t = t;
    hit.prim = i;
    hit.u = u;
    hit.v = v;
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

}  // namespace wt
