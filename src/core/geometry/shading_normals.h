#pragma once
// Per-triangle vertex normals, interpolated at a hit into the shading normal. Built only when
// some mesh of the scene has vertex normals: a flat scene stores nothing and surface_at() pays
// one empty() test per hit.

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

namespace wt {

// The unit blend (1 - u - v) n0 + u n1 + v n2, or `geometric` where it cancels or is not finite.
glm::vec3 blend_normals(const glm::vec3& n0, const glm::vec3& n1, const glm::vec3& n2, float u, float v, const glm::vec3& geometric);

// Indexed as the mesh files are: each mesh's vertex normals stored once, and three indices into
// them per triangle (12 bytes a triangle and 12 a vertex, where a copy of the three normals per
// triangle took 40 bytes a triangle).
class ShadingNormalTable {
public:
    bool empty() const { return normals_.empty(); }
    // A mesh's vertex normals; returns the index of the first, which its triangles' push()
    // indices are offset by. std::length_error past 2^32 - 1 normals in all.
    uint32_t add_vertex_normals(const std::vector<glm::vec3>& normals);
    // Indexed like TriangleSoA: one push per stored triangle or parallelogram, in its order.
    void push_flat() { corners_.push_back({kFlat, kFlat, kFlat}); }
    // The triangle's vertex normals by their indices among those added.
    void push(uint32_t n0, uint32_t n1, uint32_t n2) { corners_.push_back({n0, n1, n2}), ++smooth_count_; }
    std::size_t size() const { return corners_.size(); }
    std::size_t smooth_count() const { return smooth_count_; }
    std::size_t bytes() const { return corners_.size() * sizeof(Corners) + normals_.size() * sizeof(glm::vec3); }

    // The unit shading normal of triangle i at barycentrics (u, v) (the weights of vertices 1
    // and 2), in whichever orientation the vertex normals have; `geometric` for a flat triangle,
    // and where the vertex normals cancel (opposite normals at an edge's midpoint) or are not
    // finite, so no NaN comes out of here. Only valid when !empty().
    // Out of line: inlined into surface_at() it made g++ stop inlining surface_at() itself,
    // which costs every flat scene.
    glm::vec3 at(std::size_t i, float u, float v, const glm::vec3& geometric) const;
    // Triangle i's three vertex normals; false (and nothing written) for a flat triangle.
    bool vertex_normals(std::size_t i, glm::vec3 out[3]) const;

private:
    static constexpr uint32_t kFlat = ~uint32_t(0);
    struct Corners {
        uint32_t n0, n1, n2;  // indices into normals_, or kFlat
    };
    std::vector<Corners> corners_;  // per triangle
    std::vector<glm::vec3> normals_;
    std::size_t smooth_count_ = 0;
};

}  // namespace wt
