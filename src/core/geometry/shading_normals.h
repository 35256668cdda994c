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

class ShadingNormalTable {
public:
    bool empty() const { return records_.empty(); }
    // Indexed like TriangleSoA: one push per stored triangle or parallelogram, in its order.
    void push_flat() { record_of_.push_back(kFlat); }
    void push(const glm::vec3& n0, const glm::vec3& n1, const glm::vec3& n2);
    std::size_t size() const { return record_of_.size(); }
    std::size_t smooth_count() const { return records_.size(); }

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
    struct VertexNormals {
        glm::vec3 n0, n1, n2;
    };
    std::vector<uint32_t> record_of_;  // per triangle: index into records_, or kFlat
    std::vector<VertexNormals> records_;
};

}  // namespace wt
