#pragma once
// The light tree (Conty Estevez & Kulla 2018, "Importance Sampling of Many Lights with Adaptive
// Tree Splitting"; pbrt-v4's BVHLightSampler): a binary tree over the emissive triangles whose
// nodes hold LightBounds. A light sample at a point (and its surface normal) descends from the
// root, taking each child with probability in proportion to its importance there, and ends at one emitter; the
// product of the choices is the emitter's probability. probability() repeats the same descent
// along the emitter's path from the root, with the same arithmetic, so the pdf a BSDF-sampled ray
// weighs an emitter with is the one its light samples were drawn with.
//
// Built once, on one thread, from the emitters in the light table's order: the same scene gives
// the same tree, bit for bit.

#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "core/lights/light_bounds.h"

namespace wt {

class LightTree {
public:
    LightTree() = default;
    // `emitters[k]`: emitter k's bounds (its triangle's box and normal, cone half-angle 0).
    explicit LightTree(const std::vector<LightBounds>& emitters);

    bool empty() const { return nodes_.empty(); }
    std::size_t size() const { return trails_.size(); }  // emitters
    std::size_t node_count() const { return nodes_.size(); }
    int depth() const { return depth_; }
    std::size_t bytes() const { return nodes_.capacity() * sizeof(Node) + trails_.capacity() * sizeof(Trail); }

    struct Pick {
        uint32_t emitter;
        float probability;
    };
    // The emitter u in [0, 1) picks for the surface at `p` of normal `n`; false when no emitter
    // can light it. u is rescaled to [0, 1) at each choice (pbrt-v4 does the same), so one
    // number makes the whole descent.
    bool pick(const glm::vec3& p, const glm::vec3& n, float u, Pick& out) const;
    // The probability pick() picks `emitter` for (p, n) with.
    float probability(const glm::vec3& p, const glm::vec3& n, uint32_t emitter) const;

    // Checks of a built tree, for the tests: each node's power is its children's sum, its cone
    // holds theirs; and every emitter is reached by exactly one leaf.
    bool is_consistent() const;

private:
    struct Node {
        CompactLightBounds bounds;
        // An inner node's first child is the next node; this is its second. A leaf: its emitter.
        uint32_t second_child_or_emitter = 0;
        bool leaf = false;
    };
    // Which way each inner node on emitter k's path turns, bit d for depth d (1: second child).
    struct Trail {
        uint64_t turns = 0;
        uint32_t length = 0;
    };

    // The probability of taking node i's first child, seen from (p, n); negative when neither
    // child can light it. Shared by pick() and probability(), which is what keeps them equal.
    float first_child_probability(uint32_t i, const glm::vec3& p, const glm::vec3& n) const {
        const float first = nodes_[i + 1].bounds.importance(p, n);
        const float second = nodes_[nodes_[i].second_child_or_emitter].bounds.importance(p, n);
        const float sum = first + second;
        if (!(sum > 0.0f)) return -1.0f;
        const float p_first = first / sum;
        return p_first == p_first ? p_first : 0.5f;  // both infinite: as alike as they can be
    }

    struct Item;  // an emitter while building
    // Builds the subtree of items [begin, end), returns its root's index and sets `bounds` to its bounds.
    uint32_t build(std::vector<Item>& items, std::size_t begin, std::size_t end, uint32_t depth, uint64_t turns,
                   LightBounds& bounds);

    std::vector<Node> nodes_;   // depth first: the root at 0
    std::vector<Trail> trails_;  // per emitter
    int depth_ = 0;
};

}  // namespace wt
