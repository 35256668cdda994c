#pragma once
// Which emissive triangle a light sample goes to, when not by area (LightTable's own choice):
// in proportion to power (render.light_selection "power"), or by the light tree from the shading
// point ("bvh", core/lights/light_tree.h). Where the emitters' radiance differs, sampling by area
// spends most shadow rays on dim lights; the tree also weighs distance and orientation, so in a
// scene of thousands of emitters the few that light a point get the samples.
//
// Its pdfs include the area lights' own selection among the scene's lights (SceneLights), as
// LightTable's do. pdf_area() answers for any triangle a BSDF-sampled ray hits, from the point
// the ray left and that vertex's normal, with the same arithmetic the sample was drawn with: the
// MIS weights of the two strategies (light sample, BSDF sample) then sum to one.
//
// Built only when the setting asks for it and the scene has two emitters or more; then the
// integrators run the listed lights' samplers (core/path/listed_light_sampler.h), and a scene
// without it keeps the area lights' code and bits.

#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "core/description/estimator_settings.h"
#include "core/description/scene_description.h"
#include "core/geometry/geometry_soa.h"
#include "core/lights/light_table.h"
#include "core/lights/light_tree.h"
#include "core/lights/piecewise_constant.h"

namespace wt {

// What `setting` means for this scene: LightSelection::automatic becomes power where the scene
// has kManyEmitters or more emitters and their radiance (luminance) differs, else area, which
// power equals when every emitter emits alike; the others stay as they are. Power rather than
// the tree: it draws as cheaply as area, while the tree's descent costs a few dozen importance
// evaluations per light sample and, blind to the BSDF, can starve a glossy lobe's far lights
// (bench/README.md, "Many lights", measures the three).
constexpr std::size_t kManyEmitters = 16;  // fewer: a scene with few lights keeps today's bits
LightSelection chosen_light_selection(LightSelection setting, const LightTable& table);

class EmitterSelection {
public:
    EmitterSelection() = default;
    // `how`: power or bvh (area builds nothing; chosen_light_selection() first resolves automatic).
    // `table`: the scene's emitters, in its order.
    EmitterSelection(LightSelection how, const LightTable& table, const TriangleSoA& triangles);

    bool empty() const { return inverse_area_.empty(); }
    LightSelection how() const { return how_; }
    const LightTree& tree() const { return tree_; }
    std::size_t bytes() const {
        return power_.bytes() + tree_.bytes() + inverse_area_.capacity() * sizeof(float) +
               emitter_of_triangle_.capacity() * sizeof(uint32_t);
    }
    // The probability the area lights are picked with among the scene's lights (SceneLights).
    void set_selection_probability(float p) { selection_probability_ = p; }

    // The probability emitter k (LightTable's index) is picked for a surface at `from` of normal
    // `normal` (either side), the area lights' own selection not included.
    float probability(const glm::vec3& from, const glm::vec3& normal, uint32_t k) const {
        return how_ == LightSelection::bvh ? tree_.probability(from, normal, k) : power_.probability(k);
    }

    // Light sample (u_choice, u0, u1) of the emitters for (from, normal); false when none can be
    // picked (the tree: no emitter can light it). out.pdf_area includes every choice.
    bool sample(const LightTable& table, const glm::vec3& from, const glm::vec3& normal, float u_choice, float u0, float u1,
                LightSample& out) const {
        uint32_t k = 0;
        float p = 0.0f;
        if (how_ == LightSelection::bvh) {
            LightTree::Pick pick;
            if (!tree_.pick(from, normal, u_choice, pick)) return false;
            k = pick.emitter, p = pick.probability;
        } else {
            float rescaled = 0.0f;
            k = uint32_t(power_.pick(u_choice, rescaled));
            p = power_.probability(k);
        }
        out = table.sample_emitter(k, u0, u1);
        out.pdf_area = selection_probability_ * p * inverse_area_[k];
        return out.pdf_area > 0.0f;
    }

    // The pdf per unit area with which sample() for (from, normal) lands on scene triangle
    // `triangle`: 0 for a triangle that is no emitter (and for an instance's, which never are).
    float pdf_area(const glm::vec3& from, const glm::vec3& normal, uint32_t triangle) const {
        if (triangle >= emitter_of_triangle_.size()) return 0.0f;
        const uint32_t k = emitter_of_triangle_[triangle];
        if (k == kNoEmitter) return 0.0f;
        return selection_probability_ * probability(from, normal, k) * inverse_area_[k];
    }

private:
    static constexpr uint32_t kNoEmitter = 0xffffffffu;

    LightSelection how_ = LightSelection::area;
    DiscreteDistribution power_;  // "power": a cdf, bisected
    LightTree tree_;              // "bvh"
    std::vector<float> inverse_area_;            // per emitter
    std::vector<uint32_t> emitter_of_triangle_;  // per scene triangle, or kNoEmitter
    float selection_probability_ = 1.0f;
};

}  // namespace wt
