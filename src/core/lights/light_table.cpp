#include "core/lights/light_table.h"

#include <glm/geometric.hpp>

#include "core/base/ray_offset.h"

namespace wt {

LightTable::LightTable(const TriangleSoA& triangles, const std::vector<Material>& materials,
                       const std::vector<MipPyramid>& textures, const TextureCoordinateTable& coordinates) {
    double running_area = 0.0;
    std::vector<double> cumulative;
    for (uint32_t i = 0; i < triangles.size(); ++i) {
        const Material& m = materials[triangles.material[i]];
        if (!m.is_emissive()) continue;
        const bool parallelogram = triangles.is_parallelogram(i);
        const double area = emitter_area(triangles, i);
        if (area <= 0.0) continue;  // the loader rejects degenerate lights; built-in scenes may not
        running_area += area;
        cumulative.push_back(running_area);
        const glm::vec3 v0 = triangles.vertex0(i), e1 = triangles.edge1(i), e2 = triangles.edge2(i);
        emission_textures_.push(m.emission_texture, triangles, i, coordinates, textures);
        emitters_.push_back({v0, e1, e2, triangles.normal(i), m.emission, 0.0f, magnitude(v0), magnitude(e1), magnitude(e2),
                             parallelogram, emission_textures_.textured(emitters_.size())});
        triangles_.push_back(i);
    }
    total_area_ = float(running_area);
    pdf_area_ = 1.0f / total_area_;
    pdf_area_alone_ = pdf_area_;
    for (std::size_t k = 0; k < emitters_.size(); ++k) emitters_[k].cdf = float(cumulative[k] / running_area);
    if (!emitters_.empty()) emitters_.back().cdf = 1.0f;  // so u_choice < 1 always finds an entry
    candidates_ = emitters_.empty() ? 0 : emitters_.size() - 1;
}

}  // namespace wt
