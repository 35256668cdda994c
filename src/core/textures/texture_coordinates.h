#pragma once
// Per-triangle texture coordinates (glTF's TEXCOORD_0, OBJ's vt), interpolated at a hit. Built
// only when some material of the scene has a texture: any other scene stores nothing and no
// kernel reads it.

#include <cstddef>
#include <vector>

#include <glm/vec2.hpp>

namespace wt {

class TextureCoordinateTable {
public:
    bool empty() const { return records_.empty(); }
    std::size_t size() const { return records_.size(); }
    std::size_t bytes() const { return records_.capacity() * sizeof(Record); }

    // Indexed like TriangleSoA: one push per stored triangle, in its order. world_area is the
    // triangle's area; a triangle without coordinates pushes (0, 0) thrice.
    void push(glm::vec2 uv0, glm::vec2 uv1, glm::vec2 uv2, float world_area);

    // The coordinates of triangle i at barycentrics (u, v) (the weights of vertices 1 and 2).
    glm::vec2 at(std::size_t i, float u, float v) const {
        const Record& r = records_[i];
        return (1.0f - u - v) * r.uv0 + u * r.uv1 + v * r.uv2;
    }
    // 0.5 log2(texture-space area / world area) of triangle i, in units of the texture's extent:
    // Akenine-Moller et al. 2019's (eq. 34) triangle term of the ray cone's level of detail; -inf
    // for a triangle without coordinates (level 0).
    float log2_density(std::size_t i) const { return records_[i].log2_density; }

private:
    struct Record {
        glm::vec2 uv0, uv1, uv2;
        float log2_density;
    };
    std::vector<Record> records_;
};

}  // namespace wt
