#include "core/geometry/texture_coordinates.h"

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

// `values` appended to `rows` (the fill for a mesh without), once `rows` holds something or
// `values` does; the vertices before the first such mesh get the fill too.
template <typename T>
void append_lazily(std::vector<T>& rows, std::size_t vertices_before, std::size_t count, const std::vector<T>& values, const T& fill) {
    if (rows.empty() && values.empty()) return;
    rows.resize(vertices_before, fill);
    if (values.empty()) rows.resize(vertices_before + count, fill);
    else rows.insert(rows.end(), values.begin(), values.end());
}

}  // namespace

void TextureCoordinateTable::add_vertices(std::size_t count, const std::vector<glm::vec2>& uvs, const std::vector<glm::vec2>& second_uvs,
                                          const std::vector<glm::vec4>& tangents) {
    const std::size_t before = uv_.size();
    if (uvs.empty()) uv_.resize(before + count, glm::vec2(0.0f));
    else uv_.insert(uv_.end(), uvs.begin(), uvs.end());
    append_lazily(second_uv_, before, count, second_uvs, glm::vec2(0.0f));
    append_lazily(vertex_tangents_, before, count, tangents, glm::vec4(0.0f));
}

void TextureCoordinateTable::push_triangle(const std::array<uint32_t, 3>& c, float world_area) {
    density_.push_back(log2_texel_density(uv_[c[0]], uv_[c[1]], uv_[c[2]], world_area));
    if (second_uv_.empty()) return;
    second_density_.resize(density_.size() - 1, -INFINITY);
    second_density_.push_back(log2_texel_density(second_uv_[c[0]], second_uv_[c[1]], second_uv_[c[2]], world_area));
}

TextureCoordinateTable::TangentFrame TextureCoordinateTable::tangent_frame(const TriangleSoA& t, std::size_t i) const {
    // e1 = du1 T + dv1 B', e2 = du2 T + dv2 B' (B' = dP/dv), solved by Cramer's rule.
    const glm::vec2 uv0 = uv_[t.i0[i]], uv1 = uv_[t.i1[i]], uv2 = uv_[t.i2[i]];
    const TriangleSoA::Corner c = t.corner(i);
    TangentFrame f{glm::vec3(0.0f), glm::vec3(0.0f)};
    const float det = (uv1.x - uv0.x) * (uv2.y - uv0.y) - (uv2.x - uv0.x) * (uv1.y - uv0.y);
    if (det != 0.0f && std::isfinite(1.0f / det)) {
        const float r = 1.0f / det;
        f.tangent = (c.e1 * (uv2.y - uv0.y) - c.e2 * (uv1.y - uv0.y)) * r;
        f.bitangent = -(c.e2 * (uv1.x - uv0.x) - c.e1 * (uv2.x - uv0.x)) * r;
        if (!std::isfinite(f.tangent.x + f.tangent.y + f.tangent.z + f.bitangent.x + f.bitangent.y + f.bitangent.z))
            f = {glm::vec3(0.0f), glm::vec3(0.0f)};
    }
    return f;
}

}  // namespace wt
