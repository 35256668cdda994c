#pragma once
// Per-triangle texture coordinates (glTF's TEXCOORD_0, OBJ's vt), interpolated at a hit. Built
// only when some material of the scene has a texture: any other scene stores nothing and no
// kernel reads it; the vertex tangents only when some normal-mapped mesh has them.

#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace wt {

class TextureCoordinateTable {
public:
    bool empty() const { return records_.empty(); }
    std::size_t size() const { return records_.size(); }
    std::size_t bytes() const {
        return records_.capacity() * sizeof(Record) + vertex_tangents_.capacity() * sizeof(VertexTangents) +
               second_.capacity() * sizeof(Second);
    }

    // Indexed like TriangleSoA: one push per stored triangle, in its order. world_area is the
    // triangle's area, e1 and e2 its edges v1 - v0 and v2 - v0; a triangle without coordinates
    // pushes (0, 0) thrice.
    void push(glm::vec2 uv0, glm::vec2 uv1, glm::vec2 uv2, float world_area, const glm::vec3& e1 = glm::vec3(0.0f),
              const glm::vec3& e2 = glm::vec3(0.0f));
    // The last pushed triangle's vertex tangents (TriangleMesh::tangents: xyz, w the bitangent's
    // side, w = 0 none). Stored only once some triangle has them: until then a table holds
    // exactly what it held before tangents were read, and rows before the first are none.
    void set_vertex_tangents(const glm::vec4& t0, const glm::vec4& t1, const glm::vec4& t2);
    // The last pushed triangle's second coordinates (glTF's TEXCOORD_1), stored as the vertex
    // tangents are: only once some triangle has them, (0, 0) for the rows before.
    void set_second_coordinates(glm::vec2 uv0, glm::vec2 uv1, glm::vec2 uv2, float world_area);

    // The coordinates of triangle i at barycentrics (u, v) (the weights of vertices 1 and 2).
    glm::vec2 at(std::size_t i, float u, float v) const {
        const Record& r = records_[i];
        return (1.0f - u - v) * r.uv0 + u * r.uv1 + v * r.uv2;
    }
    // Set `set` (TextureImage::coordinate_set) of triangle i at (u, v): set 1 is (0, 0) where
    // the triangle has none.
    glm::vec2 at(std::size_t i, float u, float v, int set) const {
        if (set == 0) return at(i, u, v);
        if (i >= second_.size()) return glm::vec2(0.0f);
        const Second& r = second_[i];
        return (1.0f - u - v) * r.uv0 + u * r.uv1 + v * r.uv2;
    }
    float log2_density(std::size_t i, int set) const {
        if (set == 0) return log2_density(i);
        return i < second_.size() ? second_[i].log2_density : -INFINITY;
    }
    // 0.5 log2(texture-space area / world area) of triangle i, in units of the texture's extent:
    // Akenine-Moller et al. 2019's (eq. 34) triangle term of the ray cone's level of detail; -inf
    // for a triangle without coordinates (level 0).
    float log2_density(std::size_t i) const { return records_[i].log2_density; }
    // Triangle i's tangent frame for normal maps: dP/du and -dP/dv (glTF's normal maps have +y
    // up in the image, where v grows downwards), solved from its edges and their coordinate
    // differences (Lengyel 2001); zero where the coordinates are degenerate (no normal map).
    const glm::vec3& tangent(std::size_t i) const { return records_[i].tangent; }
    const glm::vec3& bitangent(std::size_t i) const { return records_[i].bitangent; }
    // Triangle i's three vertex tangents (TriangleMesh::tangents: xyz, w the bitangent's side),
    // or null where it has none (then tangent() and bitangent() are its frame).
    const std::array<glm::vec4, 3>* vertex_tangents(std::size_t i) const {
        if (i >= vertex_tangents_.size()) return nullptr;
        const std::array<glm::vec4, 3>& t = vertex_tangents_[i];
        return t[0].w == 0.0f || t[1].w == 0.0f || t[2].w == 0.0f ? nullptr : &t;
    }

private:
    struct Record {
        glm::vec2 uv0, uv1, uv2;
        float log2_density;
        glm::vec3 tangent, bitangent;
    };
    std::vector<Record> records_;
    struct Second {
        glm::vec2 uv0, uv1, uv2;
        float log2_density;
    };
    std::vector<Second> second_;  // empty, or one per record
    using VertexTangents = std::array<glm::vec4, 3>;
    std::vector<VertexTangents> vertex_tangents_;  // empty, or one per record
};

}  // namespace wt
