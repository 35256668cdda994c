#pragma once
// Polygons as triangles, the same way for every format.

#include <array>
#include <cstdint>
#include <vector>

namespace wt {

// The fan (p0, p1, p2), (p0, p2, p3), ...: exact for the convex polygons mesh files hold (a
// concave one would need ear clipping); it keeps the polygon's winding, so its front face.
inline void append_polygon_fan(const std::vector<uint32_t>& polygon, std::vector<std::array<uint32_t, 3>>& out) {
    for (std::size_t k = 1; k + 1 < polygon.size(); ++k) out.push_back({polygon[0], polygon[k], polygon[k + 1]});
}

}  // namespace wt
