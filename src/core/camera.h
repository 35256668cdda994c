#pragma once
// Pinhole camera: maps a film position (pixels, y down) to a primary ray.

#include <cmath>
#include <optional>

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
        inv_half_width2_ = 1.0f / (half_width * half_width);
        inv_half_height2_ = 1.0f / (half_height * half_height);
        pixel_area_ = (2.0f * half_width / width_) * (2.0f * half_height / height_);
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

    // Where the camera sees a point: the inverse of generate_ray. `importance` is what turns
    // radiance arriving at the eye from a point on a surface into that pixel's estimate, per
    // unit area of the surface and per cosine at it: the pixel value is the mean of the
    // radiance over the pixel's area on the image plane (at distance 1), whose element is
    // dA = dw / cos^3(theta) for the ray's angle theta to the view axis, and dw = cos dA_surface
    // / dist^2, so a point contributes radiance * cos / dist^2 * importance, importance =
    // 1 / (pixel area * cos^3 theta) (pbrt-v4's PerspectiveCamera::We, per pixel).
    struct FilmPoint {
        float x, y;        // film position, as generate_ray takes it
        float importance;  // 1 / (pixel area * cos^3 theta)
    };
    // Empty for a point behind the eye or outside the image.
    std::optional<FilmPoint> film_point(const glm::vec3& p) const {
        const glm::vec3 v = p - eye_;
        const float z = glm::dot(v, forward_);
        if (!(z > 0.0f)) return std::nullopt;
        const float sx = glm::dot(v, right_) * inv_half_width2_ / z;
        const float sy = glm::dot(v, up_) * inv_half_height2_ / z;
        const float x = 0.5f * (sx + 1.0f) * width_, y = 0.5f * (1.0f - sy) * height_;
        if (!(x >= 0.0f && x < width_ && y >= 0.0f && y < height_)) return std::nullopt;
        const float cos_theta = z / glm::length(v);
        return FilmPoint{x, y, 1.0f / (pixel_area_ * cos_theta * cos_theta * cos_theta)};
    }

private:
    glm::vec3 eye_{0.0f}, forward_{1, 0, 0}, right_{0, -1, 0}, up_{0, 0, 1};
    float width_ = 1.0f, height_ = 1.0f;
    float inv_half_width2_ = 1.0f, inv_half_height2_ = 1.0f, pixel_area_ = 4.0f;
};

}  // namespace wt
