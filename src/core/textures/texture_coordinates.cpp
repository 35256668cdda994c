#include "core/textures/texture_coordinates.h"

#include <cmath>

namespace wt {

namespace {

// 0.5 log2(uv area / world area); a zero uv area (no coordinates, or a degenerate mapping)
// gives -inf: level 0, never NaN.
float log2_texel_density(glm::vec2 uv0, glm::vec2 uv1, glm::vec2 uv2, float world_area) {
    const glm::vec2 d1 = uv1 - uv0, d2 = uv2 - uv0;
    const float uv_area = 0.5f * std::fabs(d1.x * d2.y - d1.y * d2.x);
    const float density = uv_area > 0.0f && world_area > 0.0f ? 0.5f * std::log2(uv_area / world_area) : -INFINITY;
    return std::isfinite(density) ? density : -INFINITY;
}

}  // namespace

void TextureCoordinateTable::push(glm::vec2 uv0, glm::vec2 uv1, glm::vec2 uv2, float world_area, const glm::vec3& e1,
                                  const glm::vec3& e2) {
    const float density = log2_texel_density(uv0, uv1, uv2, world_area);
    // e1 = du1 T + dv1 B', e2 = du2 T + dv2 B' (B' = dP/dv), solved by Cramer's rule.
    glm::vec3 tangent(0.0f), bitangent(0.0f);
    const float det = (uv1.x - uv0.x) * (uv2.y - uv0.y) - (uv2.x - uv0.x) * (uv1.y - uv0.y);
    if (det != 0.0f && std::isfinite(1.0f / det)) {
        const float r = 1.0f / det;
        tangent = (e1 * (uv2.y - uv0.y) - e2 * (uv1.y - uv0.y)) * r;
        bitangent = -(e2 * (uv1.x - uv0.x) - e1 * (uv2.x - uv0.x)) * r;
        if (!std::isfinite(tangent.x + tangent.y + tangent.z + bitangent.x + bitangent.y + bitangent.z))
            tangent = bitangent = glm::vec3(0.0f);
    }
    records_.push_back({uv0, uv1, uv2, density, tangent, bitangent});
}

void TextureCoordinateTable::set_vertex_tangents(const glm::vec4& t0, const glm::vec4& t1, const glm::vec4& t2) {
    if (records_.empty()) return;
    if (vertex_tangents_.size() < records_.size()) vertex_tangents_.resize(records_.size(), VertexTangents{glm::vec4(0.0f), glm::vec4(0.0f), glm::vec4(0.0f)});
    vertex_tangents_.back() = VertexTangents{t0, t1, t2};
}

void TextureCoordinateTable::set_second_coordinates(glm::vec2 uv0, glm::vec2 uv1, glm::vec2 uv2, float world_area) {
    if (records_.empty()) return;
    if (second_.size() < records_.size()) second_.resize(records_.size(), Second{glm::vec2(0.0f), glm::vec2(0.0f), glm::vec2(0.0f), -INFINITY});
    second_.back() = Second{uv0, uv1, uv2, log2_texel_density(uv0, uv1, uv2, world_area)};
}

}  // namespace wt
