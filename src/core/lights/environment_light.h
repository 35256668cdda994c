#pragma once
// The environment: radiance arriving from infinitely far away, from every direction a ray
// leaves the scene by. Constant, or an equirectangular map (EnvironmentMap: column u with the
// azimuth phi = atan2(y, x) - rotation from -pi at the left edge, row v with the polar angle
// theta = acos(z) from +z at the top; each texel's radiance is constant over it).
//
// A map is importance-sampled by its texels: a piecewise-constant distribution over the unit
// square with each texel weighted by its luminance times sin(theta) at its centre, the solid
// angle its row covers (pbrt's infinite area light: Pharr, Jakob & Humphreys, "Physically Based
// Rendering", 3rd ed., sec. 14.2.4), and the density per unit solid angle is the square's over
// the Jacobian 2 pi^2 sin(theta). A constant environment is sampled uniformly over the sphere.

#include <memory>

#include <glm/vec3.hpp>

#include "core/lights/piecewise_constant.h"
#include "core/description/scene_description.h"

namespace wt {

struct EnvironmentSample {
    glm::vec3 direction;  // towards the environment
    glm::vec3 radiance;   // arriving from there
    float pdf;            // per unit solid angle
};

class EnvironmentLight {
public:
    EnvironmentLight() = default;
    // A constant (`map` null: `radiance`) or map environment (its texels times `strength`).
    EnvironmentLight(const LightDescription& d);

    // The radiance a ray travelling along the unit vector `d` sees.
    glm::vec3 radiance(const glm::vec3& d) const;
    EnvironmentSample sample(float u0, float u1) const;
    float pdf(const glm::vec3& d) const;
    // The integral of the radiance's luminance over the sphere: what light selection by power
    // weighs, times the area pi r^2 of the disk the scene's bounding sphere shows it (pbrt-v4's
    // ImageInfiniteLight::Phi).
    double luminance_integral() const { return luminance_integral_; }

    // The map's texel coordinates (u, v) in [0, 1)^2 of direction d, and back.
    glm::vec2 map_point(const glm::vec3& d) const;
    glm::vec3 direction(glm::vec2 map_point) const;

    // The map's texels and its sampling distribution.
    std::size_t bytes() const {
        return (map_ ? map_->rgb.capacity() * sizeof(float) : 0) + distribution_.bytes();
    }

private:
    glm::vec3 texel(glm::vec2 p) const;

    std::shared_ptr<const EnvironmentMap> map_;  // null for a constant environment
    glm::vec3 constant_{0.0f};
    float strength_ = 1.0f;
    float rotation_ = 0.0f;  // radians about +z
    PiecewiseConstant2D distribution_;
    double luminance_integral_ = 0.0;
};

// Rec. 709 luminance of linear RGB: the weight of light in selection and map sampling.
inline double luminance(const glm::vec3& c) { return 0.2126 * double(c.x) + 0.7152 * double(c.y) + 0.0722 * double(c.z); }

}  // namespace wt
