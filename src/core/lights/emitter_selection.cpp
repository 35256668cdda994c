#include "core/lights/emitter_selection.h"

#include <algorithm>

#include <glm/geometric.hpp>

#include "core/lights/environment_light.h"

namespace wt {

namespace {

constexpr double kPiDouble = 3.14159265358979323846;

// Emitter k's bounds: its triangle's (or parallelogram's) box, its power, its normal as a cone
// of half-angle 0.
LightBounds emitter_bounds(const TriangleSoA& triangles, uint32_t i, double power) {
    const glm::vec3 v0 = triangles.vertex0(i), e1 = triangles.edge1(i), e2 = triangles.edge2(i);
    LightBounds b;
    b.lo = glm::min(v0, glm::min(v0 + e1, v0 + e2));
    b.hi = glm::max(v0, glm::max(v0 + e1, v0 + e2));
    if (triangles.is_parallelogram(i)) b.lo = glm::min(b.lo, v0 + e1 + e2), b.hi = glm::max(b.hi, v0 + e1 + e2);
    b.power = float(power);
    b.axis = triangles.normal(i);
    b.cos_theta_o = 1.0f;
    return b;
}

}  // namespace

LightSelection chosen_light_selection(LightSelection setting, const LightTable& table) {
    if (setting != LightSelection::automatic) return setting;
    if (table.size() < kManyEmitters) return LightSelection::area;
    const double first = luminance(table.mean_radiance(0));
    for (std::size_t k = 1; k < table.size(); ++k)
        if (luminance(table.mean_radiance(k)) != first) return LightSelection::power;
    return LightSelection::area;
}

EmitterSelection::EmitterSelection(LightSelection how, const LightTable& table, const TriangleSoA& triangles)
    : how_(how) {
    if (how == LightSelection::area || how == LightSelection::automatic || table.empty()) return;
    std::vector<double> power(table.size());
    inverse_area_.resize(table.size());
    emitter_of_triangle_.assign(triangles.size(), kNoEmitter);
    for (std::size_t k = 0; k < table.size(); ++k) {
        const uint32_t i = table.triangle_of(k);
        const double area = emitter_area(triangles, i);
        // An emission texture counts by its mean (LightTable::mean_radiance): the pick and the pdf
        // both read this one table, so they agree whatever the texture.
        power[k] = kPiDouble * area * luminance(table.mean_radiance(k));
        inverse_area_[k] = float(1.0 / area);
        emitter_of_triangle_[i] = uint32_t(k);
    }
    if (how == LightSelection::bvh) {
        std::vector<LightBounds> bounds(table.size());
        for (std::size_t k = 0; k < table.size(); ++k) bounds[k] = emitter_bounds(triangles, table.triangle_of(k), power[k]);
        tree_ = LightTree(bounds);
        return;
    }
    // Every emitter keeps at least a thousandth of an equal share (SceneLights' rule): one whose
    // share rounded to zero would never be sampled, and with nee nothing else would count it.
    double total = 0.0;
    for (double p : power) total += p;
    for (double& p : power) p = std::max(p, 1e-3 * total / double(power.size()));
    power_ = DiscreteDistribution(power);
}

}  // namespace wt
