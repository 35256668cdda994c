#include "core/textures/texture_coordinates.h"

#include <cmath>

namespace wt {

void TextureCoordinateTable::push(glm::vec2 uv0, glm::vec2 uv1, glm::vec2 uv2, float world_area) {
    const glm::vec2 e1 = uv1 - uv0, e2 = uv2 - uv0;
    const float uv_area = 0.5f * std::fabs(e1.x * e2.y - e1.y * e2.x);
    // A zero uv area (no coordinates, or a degenerate mapping) gives -inf: level 0, never NaN.
    const float density = uv_area > 0.0f && world_area > 0.0f ? 0.5f * std::log2(uv_area / world_area) : -INFINITY;
    records_.push_back({uv0, uv1, uv2, std::isfinite(density) ? density : -INFINITY});
}

}  // namespace wt
