#include "core/light_table.h"

#include <glm/geometric.hpp>

#include "core/ray_offset.h"
#include "core/sampling.h"

namespace wt {

LightTable::LightTable(const TriangleSoA& triangles, const std::vector<Material>& materials) {
    double running_area = 0.0;
    std::vector<double> cumulative;
    for (uint32_t i = 0; i < triangles.size(); ++i) {
        const Material& m = materials[triangles.material[i]];
        if (!m.is_emissive()) continue;
        const bool parallelogram = triangles.is_parallelogram(i);
        const double area = (parallelogram ? 1.0 : 0.5) * double(glm::length(glm::cross(triangles.edge1(i), triangles.edge2(i))));
        if (area <= 0.0) continue;  // the loader rejects degenerate lights; built-in scenes may not
        running_area += area;
        cumulative.push_back(running_area);
        emitters_.push_back({triangles.vertex0(i), triangles.edge1(i), triangles.edge2(i), triangles.normal(i), m.emission, 0.0f,
                             parallelogram});
    }
    total_area_ = float(running_area);
    for (std::size_t k = 0; k < emitters_.size(); ++k) emitters_[k].cdf = float(cumulative[k] / running_area);
    if (!emitters_.empty()) emitters_.back().cdf = 1.0f;  // so u_choice < 1 always finds an entry
}

LightSample LightTable::sample(const TriangleSoA&, float u_choice, float u0, float u1) const {
    // A linear scan: scenes have a handful of emitters, and it is branch-predictable.
    std::size_t k = 0;
    while (k + 1 < emitters_.size() && !(u_choice < emitters_[k].cdf)) ++k;
    const Emitter& e = emitters_[k];
    const glm::vec2 b = e.parallelogram ? glm::vec2(u0, u1) : sample_uniform_triangle(u0, u1);
    LightSample s;
    s.position = e.v0 + b.x * e.e1 + b.y * e.e2;
    s.error = triangle_point_error(e.v0, e.e1, e.e2, b.x, b.y);
    s.normal = e.normal;
    s.radiance = e.radiance;
    s.pdf_area = 1.0f / total_area_;
    return s;
}

}  // namespace wt
