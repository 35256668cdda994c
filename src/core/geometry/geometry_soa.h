#pragma once
// Geometry as structure-of-arrays buffers: one array per component.

#include <cstddef>
#include <cstdint>
#include <vector>

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

// Triangles as meshes store them: each vertex once, three indices per triangle (v0 first), so a
// mesh costs 16 bytes a triangle and 12 a vertex (about 22 bytes a triangle for a closed mesh),
// where rows of v0, the edges and the scaled normal took 52. What a test reads is derived from
// them, bit for bit what rows computed once would hold (-ffp-contract=off makes every rounding
// the same everywhere): the edges v1 - v0 and v2 - v0, for Moller-Trumbore their cross product
// cross(e1, e2) unnormalized (the "scaled normal", twice the area long), for the watertight test
// the vertices as given (rebuilt as v0 + e1 they would round differently in neighbouring
// triangles, and the shared edge would no longer be shared). The kernels that load N triangles
// at a time read rows copied from here (kernels/primitives/triangle_rows.h) or a BVH's leaves.
// A scene is stored for its own test (store_only_for), which decides the corners vertex1() and
// vertex2() return; a default TriangleSoA serves both.
//
// The first `parallelogram_count` entries are parallelograms, not triangles: the same v0, e1,
// e2 and normal, covering v0 + u e1 + v e2 for (u, v) in the unit square instead of the
// triangle u + v <= 1. A rectangle is then one intersection test instead of two. Everything
// downstream of a hit (position, error bound, normal, material) reads the same fields either
// way; only the inside test and light sampling differ. Only the Moller-Trumbore test knows
// parallelograms: build_scene() splits quads into triangles for the watertight test.
struct TriangleSoA {
    AlignedVector<float> px, py, pz;      // the vertices
    AlignedVector<uint32_t> i0, i1, i2;   // per entry, its vertices' indices
    AlignedVector<uint32_t> material;
    uint32_t parallelogram_count = 0;

    std::size_t size() const { return material.size(); }
    std::size_t vertex_count() const { return px.size(); }
    // Store for `test` from now on; std::logic_error once a triangle is stored.
    void store_only_for(TriangleTest test);
    bool has_vertices() const { return keeps_vertices_; }          // serves the watertight test
    bool has_scaled_normal() const { return keeps_scaled_normal_; }  // serves Moller-Trumbore
    // Whether `test` finds its corners here (no triangles: nothing to read).
    bool serves(TriangleTest test) const {
        return size() == 0 || (test == TriangleTest::watertight ? keeps_vertices_ : keeps_scaled_normal_);
    }
    std::size_t bytes() const;
    bool is_parallelogram(std::size_t i) const { return i < parallelogram_count; }

    // Room for the meshes' vertices and triangles before they are added, so that a mesh of
    // millions of triangles is not copied at every doubling of the arrays (each copy into
    // pages the kernel must first zero). `meshes`: any range of TriangleMesh.
    template <typename Meshes>
    void reserve_for(const Meshes& meshes) {
        std::size_t vertices = vertex_count(), triangles = size();
        for (const auto& mesh : meshes) vertices += mesh.vertices.size(), triangles += mesh.triangles.size();
        for (auto* row : {&px, &py, &pz}) row->reserve(vertices);
        for (auto* row : {&i0, &i1, &i2, &material}) row->reserve(triangles);
    }

    // Vertices for the triangles pushed after; returns the index of the first, which push()'s
    // indices are offset by. std::length_error past 2^31 - 1 vertices in all.
    uint32_t add_vertices(const std::vector<glm::vec3>& vertices);
    // The triangle of vertices a, b, c (indices among those added). A sliver (see is_sliver) is
    // stored collapsed onto a: all three indices a, so its edges are zero.
    void push(uint32_t a, uint32_t b, uint32_t c, uint32_t material_id);
    // The parallelogram with corners a, b, b + d - a, d. All parallelograms come before the
    // first triangle (std::logic_error otherwise), so kernels loop over two plain ranges.
    void push_parallelogram(uint32_t a, uint32_t b, uint32_t d, uint32_t material_id);
    // One triangle with vertices of its own (tests, benchmarks).
    void push_back(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, uint32_t material_id);
    void push_parallelogram(const glm::vec3& a, const glm::vec3& b, const glm::vec3& d, uint32_t material_id);

    // Triangle i's first vertex and edges, read once: a caller that then writes floats through a
    // pointer (a returned struct) would otherwise have them read again after every store.
    struct Corner {
        glm::vec3 v0, e1, e2;
    };
    Corner corner(std::size_t i) const {
        const glm::vec3 v0 = position(i0[i]);
        return {v0, position(i1[i]) - v0, position(i2[i]) - v0};
    }
    glm::vec3 position(uint32_t v) const { return {px[v], py[v], pz[v]}; }
    glm::vec3 vertex0(std::size_t i) const { return position(i0[i]); }
    glm::vec3 edge1(std::size_t i) const { return position(i1[i]) - vertex0(i); }
    glm::vec3 edge2(std::size_t i) const { return position(i2[i]) - vertex0(i); }
    // The other two vertices as the scene's test sees them: as given for the watertight test,
    // else v0 + e1 and v0 + e2, the corners Moller-Trumbore's v0 + u e1 + v e2 reaches.
    glm::vec3 vertex1(std::size_t i) const { return keeps_vertices_ ? position(i1[i]) : vertex0(i) + edge1(i); }
    glm::vec3 vertex2(std::size_t i) const { return keeps_vertices_ ? position(i2[i]) : vertex0(i) + edge2(i); }
    glm::vec3 scaled_normal(std::size_t i) const { return glm::cross(edge1(i), edge2(i)); }
    // The unit geometric normal; 0 for a sliver.
    glm::vec3 normal(std::size_t i) const { return unit_normal(edge1(i), edge2(i)); }
    static glm::vec3 unit_normal(const glm::vec3& e1, const glm::vec3& e2) {
        const glm::vec3 cross = glm::cross(e1, e2);
        const float length = glm::length(cross);
        return length > 0.0f ? cross / length : glm::vec3(0.0f);
    }

private:
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
