#pragma once
// Geometry as structure-of-arrays buffers: one array per component, so the intersect kernels
// read N primitives (or N rays' worth of one primitive) with contiguous vector loads.

#include <cstddef>
#include <cstdint>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "core/base/accuracy.h"
#include "core/base/aligned_vector.h"

namespace wt {

// A triangle too thin for float: the sine of the angle between its edges is below what the
// rounding of their cross product can resolve (32 units of 2^-24), so its normal is noise and
// the intersection tests return garbage distances for it (a needle 1e-7 wide was "hit" 1.7 m
// past where a ray crossed it). Such triangles are stored with zero edges and are never hit;
// the light area they cover is below 2e-6 of their bounding rectangle.
bool is_sliver(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c);

// Triangles as a vertex and the two edges leaving it (what a hit's position, error bound and
// normal are computed from), plus what the scene's triangle test reads: for Moller-Trumbore
// the edges' cross product cross(e1, e2) unnormalized (the "scaled normal", twice the area
// long); for the watertight test the other two vertices as given (rebuilt as v0 + e1 they would
// round differently in neighbouring triangles, and the shared edge would no longer be shared).
// A scene stores only its own test's rows (store_only_for); a default TriangleSoA stores both.
// The unit normal is not stored: normal(i) computes it from the edges exactly as it would have
// been stored (-ffp-contract=off makes that the same rounding everywhere).
//
// The first `parallelogram_count` entries are parallelograms, not triangles: the same v0, e1,
// e2 and normal, covering v0 + u e1 + v e2 for (u, v) in the unit square instead of the
// triangle u + v <= 1. A rectangle is then one intersection test instead of two. Everything
// downstream of a hit (position, error bound, normal, material) reads the same fields either
// way; only the inside test and light sampling differ. Only the Moller-Trumbore test knows
// parallelograms: build_scene() splits quads into triangles for the watertight test.
struct TriangleSoA {
    AlignedVector<float> v0x, v0y, v0z;
    AlignedVector<float> v1x, v1y, v1z;  // empty unless has_vertices()
    AlignedVector<float> v2x, v2y, v2z;
    AlignedVector<float> e1x, e1y, e1z;
    AlignedVector<float> e2x, e2y, e2z;
    AlignedVector<float> scaled_nx, scaled_ny, scaled_nz;  // empty unless has_scaled_normal()
    AlignedVector<uint32_t> material;
    uint32_t parallelogram_count = 0;

    std::size_t size() const { return material.size(); }
    // Store only the rows `test` reads from now on; std::logic_error once a triangle is stored.
    void store_only_for(TriangleTest test);
    bool has_vertices() const { return keeps_vertices_; }
    bool has_scaled_normal() const { return keeps_scaled_normal_; }
    // Whether `test` finds what it reads here (no triangles: nothing to read).
    bool serves(TriangleTest test) const {
        return size() == 0 || (test == TriangleTest::watertight ? keeps_vertices_ : keeps_scaled_normal_);
    }
    std::size_t bytes() const;
    // A copy of the first n entries (n <= size()), the same rows stored, bit for bit.
    TriangleSoA first(std::size_t n) const;
    bool is_parallelogram(std::size_t i) const { return i < parallelogram_count; }
    // A sliver (see is_sliver) is stored collapsed onto its first vertex.
    void push_back(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, uint32_t material_id);
    // The parallelogram with corners a, b, b + d - a, d. All parallelograms come before the
    // first triangle (std::logic_error otherwise), so kernels loop over two plain ranges.
    void push_parallelogram(const glm::vec3& a, const glm::vec3& b, const glm::vec3& d, uint32_t material_id);
    glm::vec3 vertex0(std::size_t i) const { return {v0x[i], v0y[i], v0z[i]}; }
    // The other two vertices as the scene's test sees them: as given where they are stored, else
    // v0 + e1 and v0 + e2, the corners Moller-Trumbore's v0 + u e1 + v e2 reaches.
    glm::vec3 vertex1(std::size_t i) const { return keeps_vertices_ ? glm::vec3(v1x[i], v1y[i], v1z[i]) : vertex0(i) + edge1(i); }
    glm::vec3 vertex2(std::size_t i) const { return keeps_vertices_ ? glm::vec3(v2x[i], v2y[i], v2z[i]) : vertex0(i) + edge2(i); }
    glm::vec3 edge1(std::size_t i) const { return {e1x[i], e1y[i], e1z[i]}; }
    glm::vec3 edge2(std::size_t i) const { return {e2x[i], e2y[i], e2z[i]}; }
    glm::vec3 scaled_normal(std::size_t i) const { return {scaled_nx[i], scaled_ny[i], scaled_nz[i]}; }  // only if has_scaled_normal()
    // The unit geometric normal; 0 for a sliver.
    glm::vec3 normal(std::size_t i) const { return unit_normal(glm::cross(edge1(i), edge2(i))); }

private:
    static glm::vec3 unit_normal(const glm::vec3& cross) {
        const float length = glm::length(cross);
        return length > 0.0f ? cross / length : glm::vec3(0.0f);
    }
    void push(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, uint32_t material_id);
    bool keeps_vertices_ = true, keeps_scaled_normal_ = true;
};

struct SphereSoA {
    AlignedVector<float> cx, cy, cz;
    AlignedVector<float> radius;
    AlignedVector<uint32_t> material;

    std::size_t size() const { return material.size(); }
    void push_back(const glm::vec3& center, float r, uint32_t material_id);
    glm::vec3 center(std::size_t i) const { return {cx[i], cy[i], cz[i]}; }
};

}  // namespace wt
