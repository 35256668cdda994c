#include "core/lights/light_tree.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace wt {

namespace {

constexpr double kPiD = 3.14159265358979323846;
constexpr int kBuckets = 12;  // candidate splits per axis, as pbrt-v4
// Below this depth the splits minimise the cost; from it on they halve the count, so no emitter's
// path outgrows the 64 bits of its trail (the paper's cost can split off one emitter at a time).
constexpr uint32_t kCostSplitDepth = 32;

// The paper's orientation measure M_Omega (sec. 4.4, eq. 1) for a cone of half-angle theta_o and
// emission half-angle theta_e = pi/2: the solid angle the normals can light, weighted by cosine.
double orientation_measure(float cos_theta_o) {
    const double cos_o = std::clamp(double(cos_theta_o), -1.0, 1.0);
    const double theta_o = std::acos(cos_o);
    const double theta_w = std::min(theta_o + 0.5 * kPiD, kPiD);
    const double sin_o = std::sqrt(std::max(0.0, 1.0 - cos_o * cos_o));
    return 2.0 * kPiD * (1.0 - cos_o) +
           0.5 * kPiD * (2.0 * theta_w * sin_o - std::cos(theta_o - 2.0 * theta_w) - 2.0 * theta_o * sin_o + cos_o);
}

// The surface area orientation heuristic (eq. 2): power x M_Omega x area, with pbrt-v4's
// regularisation of long thin nodes (the node's longest extent over the split axis's).
double split_cost(const LightBounds& b, double regularisation) {
    return double(b.power) * orientation_measure(b.cos_theta_o) * double(b.surface_area()) * regularisation;
}

}  // namespace

struct LightTree::Item {
    LightBounds bounds;
    glm::vec3 centroid;
    uint32_t emitter;
};

LightTree::LightTree(const std::vector<LightBounds>& emitters) {
    if (emitters.empty()) return;
    if (emitters.size() > (std::size_t(1) << 31)) throw std::length_error("LightTree: too many emitters");
    std::vector<Item> items(emitters.size());
    for (std::size_t k = 0; k < emitters.size(); ++k) items[k] = {emitters[k], emitters[k].centre(), uint32_t(k)};
    trails_.resize(emitters.size());
    nodes_.reserve(2 * emitters.size() - 1);
    LightBounds root;
    build(items, 0, items.size(), 0, 0, root);
}

uint32_t LightTree::build(std::vector<Item>& items, std::size_t begin, std::size_t end, uint32_t depth, uint64_t turns,
                          LightBounds& bounds) {
    const uint32_t index = uint32_t(nodes_.size());
    nodes_.emplace_back();
    depth_ = std::max(depth_, int(depth));
    if (end - begin == 1) {
        const Item& item = items[begin];
        nodes_[index] = {CompactLightBounds(item.bounds), item.emitter, true};
        trails_[item.emitter] = {turns, depth};
        bounds = item.bounds;
        return index;
    }
    glm::vec3 lo(INFINITY), hi(-INFINITY);
    LightBounds all;
    for (std::size_t k = begin; k < end; ++k) {
        lo = glm::min(lo, items[k].centroid), hi = glm::max(hi, items[k].centroid);
        all = unite(all, items[k].bounds);
    }
    // The split: the cheapest of kBuckets - 1 planes per axis by the centroids (eq. 2).
    std::size_t middle = begin;
    if (depth < kCostSplitDepth) {
        const glm::vec3 extent = all.hi - all.lo;
        const float longest = std::max(extent.x, std::max(extent.y, extent.z));
        double best = std::numeric_limits<double>::infinity();
        int best_axis = -1, best_plane = 0;
        for (int axis = 0; axis < 3; ++axis) {
            const float span = hi[axis] - lo[axis];
            if (!(span > 0.0f)) continue;
            const auto bucket_of = [&](const Item& item) {
                return std::min(kBuckets - 1, int(float(kBuckets) * ((item.centroid[axis] - lo[axis]) / span)));
            };
            std::array<LightBounds, kBuckets> buckets;
            std::array<std::size_t, kBuckets> counts{};
            for (std::size_t k = begin; k < end; ++k) {
                const int b = bucket_of(items[k]);
                buckets[b] = unite(buckets[b], items[k].bounds);
                ++counts[b];
            }
            const double regularisation = extent[axis] > 0.0f ? double(longest) / double(extent[axis]) : 1.0;
            for (int plane = 1; plane < kBuckets; ++plane) {
                LightBounds below, above;
                std::size_t n_below = 0, n_above = 0;
                for (int b = 0; b < plane; ++b) below = unite(below, buckets[b]), n_below += counts[b];
                for (int b = plane; b < kBuckets; ++b) above = unite(above, buckets[b]), n_above += counts[b];
                if (n_below == 0 || n_above == 0) continue;
                const double cost = split_cost(below, regularisation) + split_cost(above, regularisation);
                if (cost < best) best = cost, best_axis = axis, best_plane = plane;
            }
        }
        if (best_axis >= 0) {
            const float span = hi[best_axis] - lo[best_axis];
            const auto below = [&](const Item& item) {
                return std::min(kBuckets - 1, int(float(kBuckets) * ((item.centroid[best_axis] - lo[best_axis]) / span))) <
                       best_plane;
            };
            middle = std::size_t(std::stable_partition(items.begin() + std::ptrdiff_t(begin), items.begin() + std::ptrdiff_t(end),
                                                       below) -
                                 items.begin());
        }
    }
    if (middle == begin || middle == end) {
        // Deep, or every centroid in one place: halve by count along the longest centroid span,
        // ties broken by emitter index so the order is fully defined.
        const glm::vec3 span = hi - lo;
        const int axis = span.x >= span.y && span.x >= span.z ? 0 : span.y >= span.z ? 1 : 2;
        middle = begin + (end - begin) / 2;
        std::nth_element(items.begin() + std::ptrdiff_t(begin), items.begin() + std::ptrdiff_t(middle),
                         items.begin() + std::ptrdiff_t(end), [axis](const Item& a, const Item& b) {
                             return a.centroid[axis] < b.centroid[axis] ||
                                    (a.centroid[axis] == b.centroid[axis] && a.emitter < b.emitter);
                         });
    }
    if (depth >= 63) throw std::length_error("LightTree: a path deeper than its trail");
    LightBounds first_bounds, second_bounds;
    build(items, begin, middle, depth + 1, turns, first_bounds);
    const uint32_t second = build(items, middle, end, depth + 1, turns | (uint64_t(1) << depth), second_bounds);
    bounds = unite(first_bounds, second_bounds);
    nodes_[index].bounds = CompactLightBounds(bounds);
    nodes_[index].second_child_or_emitter = second;
    return index;
}

bool LightTree::pick(const glm::vec3& p, const glm::vec3& n, float u, Pick& out) const {
    constexpr float kBelowOne = 0x1.fffffep-1f;
    uint32_t i = 0;
    float probability = 1.0f;
    while (!nodes_[i].leaf) {
        const float p_first = first_child_probability(i, p, n);
        if (p_first < 0.0f) return false;
        if (u < p_first) {
            i = i + 1;
            probability *= p_first;
            u = std::min(u / p_first, kBelowOne);
        } else {
            i = nodes_[i].second_child_or_emitter;
            probability *= 1.0f - p_first;
            u = std::min((u - p_first) / (1.0f - p_first), kBelowOne);
        }
    }
    out = {nodes_[i].second_child_or_emitter, probability};
    return probability > 0.0f;
}

float LightTree::probability(const glm::vec3& p, const glm::vec3& n, uint32_t emitter) const {
    const Trail trail = trails_[emitter];
    uint32_t i = 0;
    float probability = 1.0f;
    for (uint32_t d = 0; d < trail.length; ++d) {
        const float p_first = first_child_probability(i, p, n);
        if (p_first < 0.0f) return 0.0f;
        if ((trail.turns >> d) & 1u) {
            i = nodes_[i].second_child_or_emitter;
            probability *= 1.0f - p_first;
        } else {
            i = i + 1;
            probability *= p_first;
        }
    }
    return probability;
}

bool LightTree::is_consistent() const {
    std::vector<int> reached(trails_.size(), 0);
    for (std::size_t i = 0; i < nodes_.size(); ++i) {
        const Node& n = nodes_[i];
        if (n.leaf) {
            if (n.second_child_or_emitter >= reached.size()) return false;
            ++reached[n.second_child_or_emitter];
            continue;
        }
        for (const Node* c : {&nodes_[i + 1], &nodes_[n.second_child_or_emitter]}) {
            const CompactLightBounds& b = c->bounds;
            // The child's cone inside the parent's: the angle between axes plus the child's
            // half-angle within the parent's, up to rounding.
            // (2 asin(|a - b| / 2), not acos(a . b): that is exact for nearly equal axes.)
            const double between = 2.0 * std::asin(std::min(1.0, 0.5 * double(glm::length(b.axis - n.bounds.axis))));
            const double child = std::acos(std::clamp(double(b.cos_theta_o), -1.0, 1.0));
            const double parent = std::acos(std::clamp(double(n.bounds.cos_theta_o), -1.0, 1.0));
            if (n.bounds.cos_theta_o > -1.0f && between + child > parent + 1e-4) return false;
        }
        const float sum = nodes_[i + 1].bounds.power + nodes_[n.second_child_or_emitter].bounds.power;
        if (n.bounds.power != sum) return false;
    }
    return std::all_of(reached.begin(), reached.end(), [](int r) { return r == 1; });
}

}  // namespace wt
