#include "core/lights/light_emission.h"

#include <cmath>

#include <glm/geometric.hpp>

#include "core/base/float_minmax.h"
#include "core/sampling/sampling.h"

namespace wt {

namespace {

// The start of a ray of an infinite light travelling along `direction`: a point uniform on the
// disk of the bounding sphere perpendicular to it, moved back by the radius (pbrt-v4's
// infinite lights' SampleLe: the disk is where every ray towards the scene crosses).
glm::vec3 point_on_disk(const BoundingSphere& sphere, const glm::vec3& direction, float u0, float u1) {
    const Frame frame(direction);
    const glm::vec2 d = sample_concentric_disk(u0, u1);
    return sphere.center + sphere.radius * (d.x * frame.tangent + d.y * frame.bitangent - direction);
}

float disk_pdf(const BoundingSphere& sphere) { return 1.0f / (kPi * sphere.radius * sphere.radius); }

bool positive(const glm::vec3& c) { return c.x > 0.0f || c.y > 0.0f || c.z > 0.0f; }

}  // namespace

EmittedRay sample_emission(const PunctualLight& light, const BoundingSphere& sphere, float u0, float u1, float u2,
                           float u3) {
    EmittedRay e;
    switch (light.type) {
        case LightType::point:
            e.origin = light.position;
            e.direction = sample_uniform_cone(u0, u1, 2.0f);  // the whole sphere
            e.pdf_position = 1.0f;
            e.pdf_direction = 0.25f * kInvPi;
            e.power = light.intensity * (4.0f * kPi);
            break;
        case LightType::spot: {
            const float one_minus_cos = 1.0f - light.cos_outer;
            e.origin = light.position;
            e.direction = glm::normalize(Frame(light.axis).to_world(sample_uniform_cone(u0, u1, one_minus_cos)));
            e.pdf_position = 1.0f;
            e.pdf_direction = 1.0f / (2.0f * kPi * one_minus_cos);
            e.power = light.spot_intensity(e.direction) / e.pdf_direction;
            break;
        }
        default:  // directional
            if (light.is_area_at_infinity()) {
                e.direction = -light.sample_cone(u0, u1);
                e.pdf_direction = light.cone_pdf();
                e.pdf_position = disk_pdf(sphere);
                e.power = light.radiance / (e.pdf_direction * e.pdf_position);
            } else {
                e.direction = light.axis;
                e.pdf_direction = 1.0f;
                e.pdf_position = disk_pdf(sphere);
                e.power = light.irradiance / e.pdf_position;
            }
            e.origin = point_on_disk(sphere, e.direction, u2, u3);
            break;
    }
    e.valid = positive(e.power) && std::isfinite(e.power.x + e.power.y + e.power.z);
    return e;
}

EmittedRay sample_emission(const EnvironmentLight& light, const BoundingSphere& sphere, float u0, float u1, float u2,
                           float u3) {
    EmittedRay e;
    const EnvironmentSample s = light.sample(u0, u1);
    if (!(s.pdf > 0.0f)) return e;
    e.direction = -s.direction;
    e.origin = point_on_disk(sphere, e.direction, u2, u3);
    e.pdf_direction = s.pdf;
    e.pdf_position = disk_pdf(sphere);
    e.power = s.radiance / (e.pdf_direction * e.pdf_position);
    e.valid = positive(e.power) && std::isfinite(e.power.x + e.power.y + e.power.z);
    return e;
}

EmissionPdf emission_pdf(const PunctualLight& light, const BoundingSphere& sphere, const glm::vec3& direction) {
    switch (light.type) {
        case LightType::point: return {1.0f, 0.25f * kInvPi};
        case LightType::spot: {
            const bool inside = glm::dot(direction, light.axis) >= light.cos_outer;
            return {1.0f, inside ? 1.0f / (2.0f * kPi * (1.0f - light.cos_outer)) : 0.0f};
        }
        default:
            if (!light.is_area_at_infinity()) return {disk_pdf(sphere), 1.0f};
            return {disk_pdf(sphere), glm::dot(direction, light.axis) >= light.cos_cone ? light.cone_pdf() : 0.0f};
    }
}

EmissionPdf emission_pdf(const EnvironmentLight& light, const BoundingSphere& sphere, const glm::vec3& direction) {
    return {disk_pdf(sphere), light.pdf(-direction)};
}

}  // namespace wt
