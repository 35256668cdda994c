#pragma once
// Point, spot and directional lights. Point and spot lights are deltas in position, a
// directional light of angle 0 a delta in direction: no BSDF sample can find them, so their
// light samples count in full, with nee as with mis. A directional light with an angle is a
// disk of directions (the sun: 0.53 degrees across) of constant radiance, sampled uniformly in
// its cone, and found by BSDF samples too: an infinitely far light beside the environment.

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "core/sampling/sampling.h"
#include "core/description/scene_description.h"

namespace wt {

struct PunctualLight {
    LightType type = LightType::point;
    glm::vec3 position{0.0f};    // point, spot
    glm::vec3 intensity{0.0f};   // point, spot: W/sr (a spot's on its axis)
    glm::vec3 axis{0.0f, 0.0f, -1.0f};  // spot: where it points; directional: where its light travels
    float cos_outer = -1.0f, cos_inner = -1.0f;  // spot: no light beyond outer, full within inner
    // Directional: irradiance (delta) or radiance (cone) and the cone's half angle as
    // cos and 1 - cos (the latter from 2 sin^2(a / 2), exact for the sun's tiny cone).
    glm::vec3 irradiance{0.0f};
    glm::vec3 radiance{0.0f};
    float cos_cone = 1.0f, one_minus_cos_cone = 0.0f;

    bool is_infinite() const { return type == LightType::directional; }
    // A directional light with an angle: BSDF samples can find it (escaped rays).
    bool is_area_at_infinity() const { return type == LightType::directional && one_minus_cos_cone > 0.0f; }

    // A spot's intensity towards unit direction d (from the light), faded by smoothstep between its cones.
    glm::vec3 spot_intensity(const glm::vec3& d) const {
        const float c = glm::dot(d, axis);
        if (c >= cos_inner) return intensity;
        if (c <= cos_outer) return glm::vec3(0.0f);
        const float t = (c - cos_outer) / (cos_inner - cos_outer);
        return intensity * (t * t * (3.0f - 2.0f * t));
    }
    // The radiance a ray travelling along d sees of a directional light with an angle (0 for a delta).
    glm::vec3 radiance_along(const glm::vec3& d) const {
        return is_area_at_infinity() && -glm::dot(d, axis) >= cos_cone ? radiance : glm::vec3(0.0f);
    }
    float cone_pdf() const { return 1.0f / (2.0f * kPi * one_minus_cos_cone); }
    // A direction towards the light, uniform in its cone.
    glm::vec3 sample_cone(float u0, float u1) const {
        return Frame(-axis).to_world(sample_uniform_cone(u0, u1, one_minus_cos_cone));
    }
};

PunctualLight make_punctual_light(const LightDescription& d);

}  // namespace wt
