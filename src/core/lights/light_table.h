#pragma once
// The emissive triangles as a sampling table. A light point is chosen with probability
// proportional to area, so the pdf with respect to area is 1 / total_area everywhere on every
// light, whatever their emission. An emitter with an emission texture returns its radiance
// times the texture at the chosen point (core/lights/emission_textures.h).

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "core/geometry/geometry_soa.h"
#include "core/base/ray_offset.h"
#include "core/sampling/sampling.h"
#include "core/description/scene_description.h"
#include "core/lights/emission_textures.h"

namespace wt {

// The area of scene triangle i, a parallelogram's whole: what the light table, the lights'
// power and the selection by power weigh an emitter by.
inline double emitter_area(const TriangleSoA& triangles, uint32_t i) {
    return (triangles.is_parallelogram(i) ? 1.0 : 0.5) * double(glm::length(glm::cross(triangles.edge1(i), triangles.edge2(i))));
}

struct LightSample {
    glm::vec3 position;
    glm::vec3 error;     // bound on the rounding error of position
    glm::vec3 normal;    // the emitting (front) side
    glm::vec3 radiance;  // emitted towards the front side
    float pdf_area;
};

class LightTable {
public:
    LightTable() = default;
    // textures and coordinates: the scene's, read only for materials with an emission texture.
    LightTable(const TriangleSoA& triangles, const std::vector<Material>& materials,
               const std::vector<MipPyramid>& textures = {}, const TextureCoordinateTable& coordinates = {});

    bool empty() const { return emitters_.empty(); }
    std::size_t size() const { return emitters_.size(); }
    float total_area() const { return total_area_; }
    float pdf_area() const { return pdf_area_; }  // of every light point sample() returns
    // 1 / total_area: the pdf of a light point when the area lights are the only lights (where
    // light paths start without a "lights" list), whatever the selection below.
    float pdf_area_alone() const { return pdf_area_alone_; }
    // With other lights (core/lights/scene_lights.h) the area lights are picked with probability
    // p, and the pdfs this table returns include it: pdf_area() becomes p / total_area.
    void set_selection_probability(float p) { pdf_area_ = p / total_area_; }

    // u_choice picks the triangle, (u0, u1) the point on it. (The triangles argument is the
    // scene's; the table keeps its own copy of what sampling reads, in one cache line per light.)
    // Inline: it runs once per shadow ray, and a call returning this struct cost a third of it.
    LightSample sample(const TriangleSoA& triangles, float u_choice, float u0, float u1) const;

    // A point (u0, u1) on emitter k (an index into this table), with pdf_area left to the caller:
    // how light selection by power or by the light tree (core/lights/emitter_selection.h) samples.
    LightSample sample_emitter(std::size_t k, float u0, float u1) const { return point_on(k, u0, u1); }
    // The scene triangle emitter k is.
    uint32_t triangle_of(std::size_t k) const { return triangles_[k]; }
    // Emitter k's radiance, times its emission texture's mean where it has one: what selection
    // by power and the light tree weigh it by (the same bits as its material's emission without).
    glm::vec3 mean_radiance(std::size_t k) const {
        return emitters_[k].textured ? emitters_[k].radiance * emission_textures_.mean(k) : emitters_[k].radiance;
    }

    // Everything one light sample reads, together: sampling touches one record, not six arrays.
    struct Emitter {
        glm::vec3 v0, e1, e2, normal, radiance;
        float cdf;  // cumulative area fraction up to and including this triangle; the last is 1
        glm::vec3 abs_v0, abs_e1, abs_e2;  // for the sample's error bound, taken once here
        bool parallelogram;  // (u, v) uniform in the unit square, not folded into the triangle
        bool textured;       // its radiance is multiplied by emission_textures_ at the point
    };
    // The table's emitters, for the SIMD shade kernels' light points (kernels/shading/light_points.h),
    // which take a table of at most kCountedEmitters emitters without textures: they pick among
    // so few by counting, as pick() does.
    const std::vector<Emitter>& emitters() const { return emitters_; }
    static constexpr std::size_t kCountedEmitters = 8;
    bool few_untextured_emitters() const {
        return emitters_.size() <= kCountedEmitters &&
               std::none_of(emitters_.begin(), emitters_.end(), [](const Emitter& e) { return e.textured; });
    }

    std::size_t bytes() const {
        return emitters_.capacity() * sizeof(Emitter) + triangles_.capacity() * sizeof(uint32_t) + emission_textures_.bytes();
    }

private:
    // The first emitter whose cdf exceeds u_choice (the last if none does, or u_choice is NaN).
    // The cdf never decreases, so that is the number of cdf entries before the last that u_choice
    // is not below. With a handful of emitters they are all counted,
    // without a branch: as an early-exit scan, which triangle a uniform u_choice picks was a coin
    // toss for the branch predictor on every shadow ray. Many emitters are bisected.
    std::size_t pick(float u_choice) const {
        const std::size_t candidates = candidates_;
        if (candidates < kCountedEmitters) {
            std::size_t k = 0;
            for (std::size_t i = 0; i < candidates; ++i) k += !(u_choice < emitters_[i].cdf);
            return k;
        }
        const auto first = std::partition_point(emitters_.begin(), emitters_.begin() + std::ptrdiff_t(candidates),
                                                [u_choice](const Emitter& e) { return !(u_choice < e.cdf); });
        return std::size_t(first - emitters_.begin());
    }

    LightSample point_on(std::size_t k, float u0, float u1) const;

    std::vector<Emitter> emitters_;
    std::vector<uint32_t> triangles_;  // per emitter, its index in the scene's triangles
    std::size_t candidates_ = 0;  // emitters_.size() - 1: the last is taken when no other is
    float total_area_ = 0.0f;
    float pdf_area_ = 0.0f;  // 1 / total_area_, divided once here rather than per sample
    float pdf_area_alone_ = 0.0f;
    EmissionTextures emission_textures_;  // empty unless some emitter is textured
};

inline LightSample LightTable::point_on(std::size_t k, float u0, float u1) const {
    const Emitter& e = emitters_[k];
    const glm::vec2 b = e.parallelogram ? glm::vec2(u0, u1) : sample_uniform_triangle(u0, u1);
    LightSample s;
    s.position = e.v0 + b.x * e.e1 + b.y * e.e2;
    s.error = triangle_point_error_from_magnitudes(e.abs_v0, e.abs_e1, e.abs_e2, b.x, b.y);
    s.normal = e.normal;
    s.radiance = e.radiance;
    if (e.textured) s.radiance *= emission_textures_.at(k, b);
    return s;
}

inline LightSample LightTable::sample(const TriangleSoA&, float u_choice, float u0, float u1) const {
    LightSample s = point_on(pick(u_choice), u0, u1);
    s.pdf_area = pdf_area_;
    return s;
}

}  // namespace wt
