#include "core/light_table.h"

#include <algorithm>

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
        const double area = 0.5 * double(glm::length(glm::cross(triangles.edge1(i), triangles.edge2(i))));
        if (area <= 0.0) continue;  // the loader rejects degenerate lights; built-in scenes may not
        running_area += area;
        triangle_.push_back(i);
        cumulative.push_back(running_area);
        radiance_.push_back(m.emission);
    }
    total_area_ = float(running_area);
    for (double c : cumulative) cdf_.push_back(float(c / running_area));
    if (!cdf_.empty()) cdf_.back() = 1.0f;  // so u_choice < 1 always finds an entry
}

LightSample LightTable::sample(const TriangleSoA& triangles, float u_choice, float u0, float u1) const {
    const std::size_t k = std::size_t(std::upper_bound(cdf_.begin(), cdf_.end(), u_choice) - cdf_.begin());
    const std::size_t index = std::min(k, cdf_.size() - 1);
    const uint32_t tri = triangle_[index];
    const glm::vec2 b = sample_uniform_triangle(u0, u1);
    LightSample s;
    s.position = triangles.vertex0(tri) + b.x * triangles.edge1(tri) + b.y * triangles.edge2(tri);
    s.error = triangle_point_error(triangles.vertex0(tri), triangles.edge1(tri), triangles.edge2(tri), b.x, b.y);
    s.normal = triangles.normal(tri);
    s.radiance = radiance_[index];
    s.pdf_area = 1.0f / total_area_;
    return s;
}

}  // namespace wt
