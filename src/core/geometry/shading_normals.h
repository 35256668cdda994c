#pragma once
// Vertex normals, interpolated at a hit into the shading normal. Built only when some mesh of
// the scene has vertex normals: a flat scene stores nothing and surface_at() pays one empty()
// test per hit.

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "core/geometry/geometry_soa.h"

namespace wt {

// The unit blend (1 - u - v) n0 + u n1 + v n2, or `geometric` where it cancels or is not finite.
glm::vec3 blend_normals(const glm::vec3& n0, const glm::vec3& n1, const glm::vec3& n2, float u, float v, const glm::vec3& geometric);

// Indexed as the triangles' positions are: one normal per vertex of the TriangleSoA (its own
// indices i0, i1, i2 find a triangle's three), so a mesh's normals cost 12 bytes a vertex and
// nothing a triangle. The vertices of flat meshes hold a NaN marker: a triangle of them keeps its
// geometric normal, which is also what blend_normals makes of a normal that is not finite.
class ShadingNormalTable {
public:
    bool empty() const { return normals_.empty(); }
    // The normals of the vertices the TriangleSoA's last add_vertices() added, in its order: once
    // the table is used, every add_vertices() has its add_vertex_normals() or add_flat_vertices().
    void add_vertex_normals(const std::vector<glm::vec3>& normals);
    void add_flat_vertices(std::size_t count);
    std::size_t size() const { return normals_.size(); }  // vertices
    std::size_t smooth_count() const { return smooth_count_; }  // vertices with a normal
    std::size_t bytes() const { return normals_.size() * sizeof(glm::vec3); }

    // The unit shading normal of triangle i of `t` at barycentrics (u, v) (the weights of
    // vertices 1 and 2), in whichever orientation the vertex normals have; `geometric` for a
    // flat triangle, and where the vertex normals cancel (opposite normals at an edge's
    // midpoint) or are not finite, so no NaN comes out of here. Only valid when !empty().
    // Out of line: inlined into surface_at() it made g++ stop inlining surface_at() itself,
    // which costs every flat scene.
    glm::vec3 at(const TriangleSoA& t, std::size_t i, float u, float v, const glm::vec3& geometric) const;
    // The normals as stored, one per vertex of the TriangleSoA, NaN in a flat mesh's: what the
    // SIMD surface kernel gathers (kernels/shading/surface_points.h).
    const glm::vec3* per_vertex() const { return normals_.data(); }
    // Triangle i's three vertex normals; false (and nothing written) for a flat triangle.
    bool vertex_normals(const TriangleSoA& t, std::size_t i, glm::vec3 out[3]) const;

private:
    std::vector<glm::vec3> normals_;  // per vertex of the TriangleSoA
    std::size_t smooth_count_ = 0;
};

// A mesh's vertices added to `triangles`, and with a table in use (`smooth`: some mesh of the
// scene has normals) its normals, or flat markers if it has none, to `normals` in step; returns
// the index of the first vertex, which the mesh's triangle indices are offset by.
uint32_t add_mesh_vertices(const std::vector<glm::vec3>& positions, const std::vector<glm::vec3>& vertex_normals, bool smooth,
                           TriangleSoA& triangles, ShadingNormalTable& normals);

}  // namespace wt
