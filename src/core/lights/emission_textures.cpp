#include "core/lights/emission_textures.h"

#include <algorithm>

#include "core/textures/texture_lookup.h"

namespace wt {

void EmissionTextures::push(int32_t texture, const TriangleSoA& triangles, uint32_t triangle,
                            const TextureCoordinateTable& coordinates, const std::vector<MipPyramid>& textures) {
    const std::size_t k = pushed_++;
    if (texture < 0 && rows_.empty()) return;
    rows_.resize(k + 1);  // the untextured emitters before the first textured one get empty rows
    if (texture < 0 || std::size_t(texture) >= textures.size()) return;
    Row& row = rows_[k];
    // The vertices' coordinates in the set the texture reads (TEXCOORD_0 or _1), as
    // TextureCoordinateTable::at gives them (exactly: the other weights are zero), so a sample
    // interpolates them with a hit's arithmetic.
    const int set = textures[std::size_t(texture)].coordinate_set();
    if (triangle < coordinates.size())
        row.uv0 = coordinates.at(triangles, triangle, 0.0f, 0.0f, set), row.uv1 = coordinates.at(triangles, triangle, 1.0f, 0.0f, set),
        row.uv2 = coordinates.at(triangles, triangle, 0.0f, 1.0f, set);
    const auto known = std::find(scene_texture_.begin(), scene_texture_.end(), texture);
    if (known != scene_texture_.end()) {
        row.texture = int32_t(known - scene_texture_.begin());
        return;
    }
    row.texture = int32_t(textures_.size());
    textures_.push_back(textures[std::size_t(texture)]);
    scene_texture_.push_back(texture);
}

glm::vec3 EmissionTextures::at(std::size_t k, glm::vec2 b) const {
    const Row& r = rows_[k];
    const MipPyramid& t = textures_[std::size_t(r.texture)];
    const glm::vec2 uv = (1.0f - b.x - b.y) * r.uv0 + b.x * r.uv1 + b.y * r.uv2;
    const glm::vec4 c = texture_lookup(t, t.transformed(uv), -INFINITY);
    return {c.x, c.y, c.z};
}

glm::vec3 EmissionTextures::mean(std::size_t k) const {
    if (k >= rows_.size() || rows_[k].texture < 0) return glm::vec3(1.0f);
    const MipPyramid& t = textures_[std::size_t(rows_[k].texture)];
    const glm::vec4& c = t.level(t.level_count() - 1).at(0, 0);
    return {c.x, c.y, c.z};
}

}  // namespace wt
