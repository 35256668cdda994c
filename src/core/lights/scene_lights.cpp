#include "core/lights/scene_lights.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "core/lights/light_table.h"

namespace wt {

namespace {
constexpr double kPiDouble = 3.14159265358979323846;
}

PunctualLight make_punctual_light(const LightDescription& d) {
    PunctualLight p;
    p.type = d.type;
    p.position = d.position;
    p.intensity = d.intensity;
    p.axis = glm::normalize(d.direction);
    if (d.type == LightType::spot) {
        const double half = 0.5 * double(d.cone_degrees) * kPiDouble / 180.0;
        p.cos_outer = float(std::cos(half));
        p.cos_inner = float(std::cos(half * (1.0 - double(d.blend))));
        // blend 0: a hard edge, full intensity up to the outer cone.
        if (!(p.cos_inner > p.cos_outer)) p.cos_inner = p.cos_outer;
    }
    if (d.type == LightType::directional) {
        p.irradiance = d.irradiance;
        const double half = 0.5 * double(d.angle_degrees) * kPiDouble / 180.0;
        if (half > 0.0) {
            const double s = std::sin(0.5 * half);
            const double one_minus_cos = 2.0 * s * s;
            p.one_minus_cos_cone = float(one_minus_cos);
            p.cos_cone = float(1.0 - one_minus_cos);
            // E = integral of L cos over the cone = L pi sin^2(half).
            const double sin_half = std::sin(half);
            p.radiance = glm::vec3(glm::dvec3(d.irradiance) / (kPiDouble * sin_half * sin_half));
        }
    }
    return p;
}

SceneLights::SceneLights(const std::vector<LightDescription>& lights, double area_power, const BoundingSphere& bounds)
    : bounds_(bounds) {
    const double disk = kPiDouble * double(bounds.radius) * double(bounds.radius);
    std::vector<double> power;
    if (area_power > 0.0) {
        entries_.push_back(-1);
        power.push_back(area_power);
    }
    for (const LightDescription& d : lights) {
        if (d.type != LightType::environment) continue;
        environment_.emplace(d);
        entries_.push_back(-2);
        power.push_back(disk * environment_->luminance_integral());
        seen_by_escaping_rays_ = true;
    }
    first_punctual_ = entries_.size();
    for (const LightDescription& d : lights) {
        if (d.type == LightType::environment) continue;
        const PunctualLight p = make_punctual_light(d);
        entries_.push_back(int(punctual_.size()));
        punctual_.push_back(p);
        if (p.is_area_at_infinity()) seen_by_escaping_rays_ = true;
        switch (p.type) {
            case LightType::point: power.push_back(4.0 * kPiDouble * luminance(p.intensity)); break;
            case LightType::spot:
                power.push_back(2.0 * kPiDouble * luminance(p.intensity) *
                                (1.0 - 0.5 * (double(p.cos_inner) + double(p.cos_outer))));
                break;
            default: power.push_back(disk * luminance(p.irradiance)); break;
        }
    }
    // Every light keeps at least a thousandth of an equal share: a light whose share rounded to
    // zero would never be sampled, and with nee nothing else would count its light.
    double total = 0.0;
    for (double p : power) total += p;
    for (double& p : power) p = std::max(p, 1e-3 * total / double(power.size()));
    selection_ = DiscreteDistribution(power);
    for (std::size_t i = 0; i < entries_.size(); ++i) {
        if (entries_[i] == -1) area_probability_ = selection_.probability(i);
        if (entries_[i] == -2) environment_probability_ = selection_.probability(i);
    }
}

int SceneLights::pick(float u, float& rescaled) const { return entries_[selection_.pick(u, rescaled)]; }

double area_light_power(const TriangleSoA& triangles, const LightTable& table) {
    // The table's emitters, in triangle order: the emissive triangles it leaves out have no area.
    double power = 0.0;
    for (std::size_t k = 0; k < table.size(); ++k)
        power += kPiDouble * emitter_area(triangles, table.triangle_of(k)) * luminance(table.mean_radiance(k));
    return power;
}

}  // namespace wt
