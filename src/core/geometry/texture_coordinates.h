#pragma once
// Texture coordinates (glTF's TEXCOORD_0 and _1, OBJ's vt) and vertex tangents, interpolated at a
// hit. Built only when some material of the scene has a texture: any other scene stores nothing
// and no kernel reads it.
//
// Indexed as the triangles' positions are (shading_normals.h): one entry per vertex of the
// TriangleSoA, found by its indices i0, i1, i2, so a mesh's coordinates cost 8 bytes a vertex,
// and per triangle only its texel density (4 bytes), where three coordinates, the density and
// the tangent frame took 52 bytes a triangle. The tangent frame is solved at the hit from the
// same coordinates and edges it was solved from when stored.

#include <array>
#include <cmath>
#include <cstddef>
#include <optional>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "core/geometry/geometry_soa.h"

namespace wt {

class TextureCoordinateTable {
public:
    bool empty() const { return density_.empty(); }
    std::size_t size() const { return density_.size(); }  // triangles
    std::size_t bytes() const {
        return uv_.capacity() * sizeof(glm::vec2) + density_.capacity() * sizeof(float) + second_uv_.capacity() * sizeof(glm::vec2) +
               second_density_.capacity() * sizeof(float) + vertex_tangents_.capacity() * sizeof(glm::vec4);
    }

    // The vertices the TriangleSoA's last add_vertices() added, `count` of them, in its order:
    // their coordinates (empty: (0, 0) each), second coordinates and tangents (TriangleMesh::
    // tangents: xyz, w the bitangent's side, w = 0 none; empty: none). Once the table is used,
    // every add_vertices() has its add_vertices() here. The second set and the tangents are
    // stored only once some vertex has them: until then the table holds exactly what it held
    // without them, and the vertices before read as (0, 0) and none.
    void add_vertices(std::size_t count, const std::vector<glm::vec2>& uvs, const std::vector<glm::vec2>& second_uvs,
                      const std::vector<glm::vec4>& tangents);
    // The next triangle's texel densities, pushed in the TriangleSoA's triangle order, from its
    // vertices' coordinates as the mesh gives them (`corners` into this table's vertices) and
    // its world area.
    void push_triangle(const std::array<uint32_t, 3>& corners, float world_area);

    // The coordinates of triangle i of `t` at barycentrics (u, v) (the weights of vertices 1
    // and 2), in set `set` (TextureImage::coordinate_set): set 1 is (0, 0) where the triangle
    // has none.
    glm::vec2 at(const TriangleSoA& t, std::size_t i, float u, float v, int set = 0) const {
        const std::vector<glm::vec2>& uv = set == 0 ? uv_ : second_uv_;
        if (set != 0 && t.i0[i] >= uv.size()) return glm::vec2(0.0f);
        return (1.0f - u - v) * uv[t.i0[i]] + u * uv[t.i1[i]] + v * uv[t.i2[i]];
    }
    // 0.5 log2(texture-space area / world area) of triangle i, in units of the texture's extent:
    // Akenine-Moller et al. 2019's (eq. 34) triangle term of the ray cone's level of detail; -inf
    // for a triangle without coordinates (level 0).
    float log2_density(std::size_t i, int set = 0) const {
        if (set == 0) return density_[i];
        return i < second_density_.size() ? second_density_[i] : -INFINITY;
    }
    // Triangle i's tangent frame for normal maps: dP/du and -dP/dv (glTF's normal maps have +y
    // up in the image, where v grows downwards), solved from its edges and their coordinate
    // differences (Lengyel 2001); zero where the coordinates are degenerate (no normal map).
    struct TangentFrame {
        glm::vec3 tangent, bitangent;
    };
    TangentFrame tangent_frame(const TriangleSoA& t, std::size_t i) const;
    // Triangle i's three vertex tangents, or none where it has none (then tangent_frame() is its
    // frame).
    std::optional<std::array<glm::vec4, 3>> vertex_tangents(const TriangleSoA& t, std::size_t i) const {
        if (t.i0[i] >= vertex_tangents_.size()) return std::nullopt;
        const std::array<glm::vec4, 3> v{vertex_tangents_[t.i0[i]], vertex_tangents_[t.i1[i]], vertex_tangents_[t.i2[i]]};
        if (v[0].w == 0.0f || v[1].w == 0.0f || v[2].w == 0.0f) return std::nullopt;
        return v;
    }

private:
    std::vector<glm::vec2> uv_;               // per vertex
    std::vector<float> density_;              // per triangle
    std::vector<glm::vec2> second_uv_;        // empty, or per vertex
    std::vector<float> second_density_;       // empty, or per triangle
    std::vector<glm::vec4> vertex_tangents_;  // empty, or per vertex
};

}  // namespace wt
