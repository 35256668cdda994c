#include "core/lights/environment_light.h"

#include <algorithm>
#include <cmath>

#include "core/sampling/sampling.h"

namespace wt {

namespace {
constexpr double kPiDouble = 3.14159265358979323846;
}

EnvironmentLight::EnvironmentLight(const LightDescription& d)
    : map_(d.map), constant_(d.radiance), strength_(d.strength), rotation_(float(double(d.rotate_degrees) * kPiDouble / 180.0)) {
    if (!map_) {
        luminance_integral_ = 4.0 * kPiDouble * luminance(constant_);
        return;
    }
    const int w = map_->width, h = map_->height;
    std::vector<double> weights(std::size_t(w) * std::size_t(h));
    double integral = 0.0;
    for (int y = 0; y < h; ++y) {
        // The exact solid angle of a texel in row y is (cos theta0 - cos theta1) 2 pi / w; sin at
        // the centre, as the density's Jacobian uses, keeps the two consistent.
        const double sin_theta = std::sin(kPiDouble * (double(y) + 0.5) / double(h));
        for (int x = 0; x < w; ++x) {
            const std::size_t i = std::size_t(y) * std::size_t(w) + std::size_t(x);
            const glm::vec3 c(map_->rgb[3 * i], map_->rgb[3 * i + 1], map_->rgb[3 * i + 2]);
            weights[i] = luminance(c) * sin_theta;
            integral += weights[i];
        }
    }
    distribution_ = PiecewiseConstant2D(weights, w, h);
    luminance_integral_ = double(strength_) * integral * 2.0 * kPiDouble * kPiDouble / (double(w) * double(h));
}

glm::vec2 EnvironmentLight::map_point(const glm::vec3& d) const {
    const float theta = std::acos(std::clamp(d.z, -1.0f, 1.0f));
    float u = (std::atan2(d.y, d.x) - rotation_) * (0.5f * kInvPi) + 0.5f;
    u -= std::floor(u);
    return {u, theta * kInvPi};
}

glm::vec3 EnvironmentLight::direction(glm::vec2 p) const {
    const float phi = (p.x - 0.5f) * 2.0f * kPi + rotation_;
    const float theta = p.y * kPi;
    const float sin_theta = std::sin(theta);
    return {sin_theta * std::cos(phi), sin_theta * std::sin(phi), std::cos(theta)};
}

glm::vec3 EnvironmentLight::texel(glm::vec2 p) const {
    const int x = std::clamp(int(p.x * float(map_->width)), 0, map_->width - 1);
    const int y = std::clamp(int(p.y * float(map_->height)), 0, map_->height - 1);
    const std::size_t i = std::size_t(y) * std::size_t(map_->width) + std::size_t(x);
    return strength_ * glm::vec3(map_->rgb[3 * i], map_->rgb[3 * i + 1], map_->rgb[3 * i + 2]);
}

glm::vec3 EnvironmentLight::radiance(const glm::vec3& d) const { return map_ ? texel(map_point(d)) : constant_; }

EnvironmentSample EnvironmentLight::sample(float u0, float u1) const {
    if (!map_) {
        // Uniform over the sphere.
        const float z = 1.0f - 2.0f * u1;
        const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
        const float phi = 2.0f * kPi * u0;
        return {{r * std::cos(phi), r * std::sin(phi), z}, constant_, 0.25f * kInvPi};
    }
    float density = 0.0f;
    const glm::vec3 d = direction(distribution_.sample(u0, u1, density));
    // The pdf and radiance of the direction as an escaping ray along it finds them (pdf(d),
    // radiance(d)), not of the square's point it came from: near the poles the two differ by
    // rounding, and the power heuristic's weights of a direction must sum to one exactly.
    return {d, radiance(d), pdf(d)};
}

float EnvironmentLight::pdf(const glm::vec3& d) const {
    if (!map_) return 0.25f * kInvPi;
    const glm::vec2 p = map_point(d);
    const float sin_theta = std::sin(p.y * kPi);
    return sin_theta > 0.0f ? distribution_.density(p) / (2.0f * kPi * kPi * sin_theta) : 0.0f;
}

}  // namespace wt
