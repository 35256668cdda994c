#pragma once
// Pinhole camera: maps a film position (pixels, y down) to a primary ray.

#include <cmath>

#include <glm/geometric.hpp>

#include "core/ray.h"
#include "core/scene_description.h"

namespace wt {

// The camera's unit basis, in float as the renderer computes it (the loader checks it is one).
struct CameraBasis {
    glm::vec3 forward, right, up;
};

inline CameraBasis camera_basis(const CameraDescription& desc) {
    const glm::vec3 forward = glm::normalize(desc.look_at - desc.eye);
    const glm::vec3 right = glm::normalize(glm::cross(forward, desc.up));
    return {forward, right, glm::cross(right, forward)};
}

class Camera {
public:
    Camera() = default;
    Camera(const CameraDescription& desc, int width, int height)
        : eye_(desc.eye), width_(float(width)), height_(float(height)) {
        const auto [forward, right, up] = camera_basis(desc);
        const float half_height = std::tan(0.5f * desc.fov_degrees * 3.14159265358979f / 180.0f);
        const float half_width = half_height * width_ / height_;
        forward_ = forward;
        right_ = right * half_width;
        up_ = up * half_height;
    }

    const glm::vec3& eye() const { return eye_; }
    // Unit vector along the view axis (towards look_at).
    const glm::vec3& forward() const { return forward_; }

    // film_x in [0, width), film_y in [0, height), (0,0) the top-left corner of the image.
    Ray generate_ray(float film_x, float film_y) const {
        const float sx = 2.0f * film_x / width_ - 1.0f;
        const float sy = 1.0f - 2.0f * film_y / height_;
        return {eye_, glm::normalize(forward_ + sx * right_ + sy * up_)};
    }

private:
    glm::vec3 eye_{0.0f}, forward_{1, 0, 0}, right_{0, -1, 0}, up_{0, 0, 1};
    float width_ = 1.0f, height_ = 1.0f;
};

}  // namespace wt
