#pragma once
// The emission textures of the light table's emitters (glTF 2.0, 3.9.5: emitted radiance is
// emissiveFactor times the emissive texture's RGB): for each textured emitter its triangle's
// texture coordinates and texture, so a light sample reads the texture at the point it chose,
// as a hit there does (core/scene/material_at_hit.cpp), at level 0, the level every ray but
// the camera's reads: a light sample and the BSDF-sampled ray that finds the same point see the
// same radiance, so their MIS weights combine estimates of one integrand. Empty (and never read)
// in a scene whose emitters have no texture.

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "core/textures/mip_pyramid.h"
#include "core/geometry/texture_coordinates.h"

namespace wt {

class EmissionTextures {
public:
    bool empty() const { return rows_.empty(); }
    // Emitter k of the table (pushed in its order, every emitter once) is scene triangle
    // `triangle`, textured by `texture` (an index into `textures`), or untextured (-1).
    void push(int32_t texture, const TriangleSoA& triangles, uint32_t triangle, const TextureCoordinateTable& coordinates,
              const std::vector<MipPyramid>& textures);

    bool textured(std::size_t k) const { return k < rows_.size() && rows_[k].texture >= 0; }
    // Emitter k's texture RGB at barycentrics b (the weights of vertices 1 and 2, as a hit's),
    // bilinear at level 0; k must be textured.
    glm::vec3 at(std::size_t k, glm::vec2 b) const;
    // The mean RGB of emitter k's texture over its whole image (its pyramid's 1 x 1 level), or 1
    // untextured: what its power is weighed by (core/lights/emitter_selection.h). Not the mean
    // over the triangle's own coordinates: a selection pdf changes the variance, never the
    // expectation, as long as every point that emits is sampled with a pdf above zero.
    glm::vec3 mean(std::size_t k) const;

    std::size_t bytes() const { return rows_.capacity() * sizeof(Row) + textures_.capacity() * sizeof(MipPyramid); }

private:
    struct Row {
        glm::vec2 uv0{0.0f}, uv1{0.0f}, uv2{0.0f};
        int32_t texture = -1;  // into textures_
    };
    std::vector<Row> rows_;  // per emitter, from the first textured one on
    // Copies of the scene's pyramids, sharing their texels (MipPyramid's levels are shared).
    std::vector<MipPyramid> textures_;
    std::vector<int32_t> scene_texture_;  // per entry of textures_, its index in the scene's
    std::size_t pushed_ = 0;  // emitters pushed so far, textured or not
};

}  // namespace wt
