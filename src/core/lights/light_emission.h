#pragma once
// Rays leaving the listed lights, for the light paths of light tracing and photons
// (kernels/caustics): where a path starts, where it goes, and the power it carries per unit of
// the pdfs it was drawn with (the idea of pbrt-v4's Light::SampleLe and PDF_Le).
//
// - Point light: its position (a delta), a direction uniform over the sphere.
// - Spot: its position, a direction uniform in its outer cone, the power weighted by its
//   falloff towards that direction (spot_intensity).
// - Directional light: a direction along the light (a delta at angle 0, else uniform in its
//   cone), and an origin uniform on the disk of the scene's bounding sphere perpendicular to that
//   direction, on the side the light comes from: every ray that could meet the scene crosses it.
// - Environment: a direction drawn as its light samples are (from the map's importance
//   distribution), the origin on the same disk.
// A delta's pdf is 1: the power is then intensity / pdf_direction for a point or spot, and
// irradiance / pdf_position for a directional light of angle 0.

#include <glm/vec3.hpp>

#include "core/lights/environment_light.h"
#include "core/lights/punctual_light.h"

namespace wt {

// A sphere that holds the scene: what the lights at infinity shine on.
struct BoundingSphere {
    glm::vec3 center{0.0f};
    float radius = 1.0f;
};

struct EmittedRay {
    glm::vec3 origin{0.0f}, direction{0.0f, 0.0f, 1.0f};  // direction: where the light travels, unit
    glm::vec3 power{0.0f};  // Le |cos| / (pdf_position pdf_direction), W
    float pdf_position = 0.0f;   // per unit area; 1 for a delta position
    float pdf_direction = 0.0f;  // per unit solid angle; 1 for a delta direction
    bool valid = false;          // false: no light this way (outside a spot's cone, a zero pdf)
};

struct EmissionPdf {
    float position, direction;  // as EmittedRay's
};

// (u0, u1) choose the direction, (u2, u3) the point on the disk (infinite lights only).
EmittedRay sample_emission(const PunctualLight& light, const BoundingSphere& sphere, float u0, float u1, float u2, float u3);
EmittedRay sample_emission(const EnvironmentLight& light, const BoundingSphere& sphere, float u0, float u1, float u2,
                           float u3);

// The pdfs with which sample_emission draws a ray travelling along unit `direction` (from a
// point on the disk, for the infinite lights; from the light's position otherwise).
EmissionPdf emission_pdf(const PunctualLight& light, const BoundingSphere& sphere, const glm::vec3& direction);
EmissionPdf emission_pdf(const EnvironmentLight& light, const BoundingSphere& sphere, const glm::vec3& direction);

}  // namespace wt
