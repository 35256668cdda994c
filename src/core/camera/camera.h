#pragma once
// The camera: maps a film position (pixels, y down) to a primary ray. A pinhole, a thin lens
// (depth of field) or an orthographic window; the pinhole is what a scene gets without asking.

#include <cmath>
#include <optional>

#include <glm/geometric.hpp>

#include "core/base/ray.h"
#include "core/sampling/sampling.h"
#include "core/description/scene_description.h"

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

// Whether a basis vector came out unit length in float: look_at - eye or up too short (1e-30
// squares to 0) or too long (1e20 squares to infinity) does not, and would render black.
inline bool is_unit_in_float(const glm::vec3& v) {
    const float length = glm::length(v);
    return std::isfinite(length) && std::fabs(length - 1.0f) < 1e-3f;
}

class Camera {
public:
    Camera() = default;
    Camera(const CameraDescription& desc, int width, int height)
        : eye_(desc.eye), width_(float(width)), height_(float(height)) {
        const auto [forward, right, up] = camera_basis(desc);
        forward_ = forward;
        unit_right_ = right;
        unit_up_ = up;
        if (desc.projection == Projection::orthographic) {
            orthographic_ = true;
            const float half_width = 0.5f * desc.width_world;
            right_ = right * half_width;
            up_ = up * (half_width * height_ / width_);
            return;
        }
        const float half_height = std::tan(0.5f * desc.fov_degrees * 3.14159265358979f / 180.0f);
        const float half_width = half_height * width_ / height_;
        right_ = right * half_width;
        up_ = up * half_height;
        inv_half_width2_ = 1.0f / (half_width * half_width);
        inv_half_height2_ = 1.0f / (half_height * half_height);
        pixel_area_ = (2.0f * half_width / width_) * (2.0f * half_height / height_);
        if (desc.aperture_radius > 0.0f) {
            lens_radius_ = desc.aperture_radius;
            focus_distance_ = desc.focus_distance > 0.0f ? desc.focus_distance : glm::length(desc.look_at - desc.eye);
        }
    }

    const glm::vec3& eye() const { return eye_; }
    // Unit vector along the view axis (towards look_at).
    const glm::vec3& forward() const { return forward_; }
    // Whether a camera ray needs a lens sample: the thin lens. The pinhole draws none.
    bool has_lens() const { return lens_radius_ > 0.0f; }
    bool is_orthographic() const { return orthographic_; }

    // film_x in [0, width), film_y in [0, height), (0,0) the top-left corner of the image. The
    // pinhole's ray, or the thin lens's through its centre, or the orthographic window's.
    Ray generate_ray(float film_x, float film_y) const {
        const float sx = 2.0f * film_x / width_ - 1.0f;
        const float sy = 1.0f - 2.0f * film_y / height_;
        if (orthographic_) return {eye_ + sx * right_ + sy * up_, forward_};
        return {eye_, glm::normalize(forward_ + sx * right_ + sy * up_)};
    }

    // The thin lens (pbrt-v4's PerspectiveCamera, Kolb et al. 1995): the pinhole's ray fixes
    // the point it reaches on the plane of focus; the ray leaves a point of the lens disk, the
    // unit square's `lens_u` mapped by Shirley and Chiu's concentric map, towards that point.
    Ray generate_ray(float film_x, float film_y, glm::vec2 lens_u) const {
        if (!has_lens()) return generate_ray(film_x, film_y);
        const float sx = 2.0f * film_x / width_ - 1.0f;
        const float sy = 1.0f - 2.0f * film_y / height_;
        const glm::vec3 focus = eye_ + focus_distance_ * (forward_ + sx * right_ + sy * up_);
        const glm::vec3 lens = lens_point(lens_u);
        return {lens, glm::normalize(focus - lens)};
    }

    // The point of the lens that `lens_u` names: the eye for the pinhole.
    glm::vec3 lens_point(glm::vec2 lens_u) const {
        if (!has_lens()) return eye_;
        const glm::vec2 d = lens_radius_ * sample_concentric_disk(lens_u.x, lens_u.y);
        return eye_ + d.x * unit_right_ + d.y * unit_up_;
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
    // Empty for a point behind the eye or outside the image widened by `margin` pixels on each
    // side (where a wide pixel filter's samples of the border pixels still land).
    // Never for the orthographic camera, whose rays have one direction: no point can be joined to it.
    std::optional<FilmPoint> film_point(const glm::vec3& p, float margin = 0.0f) const {
        if (orthographic_) return std::nullopt;
        const glm::vec3 v = p - eye_;
        const float z = glm::dot(v, forward_);
        if (!(z > 0.0f)) return std::nullopt;
        const float sx = glm::dot(v, right_) * inv_half_width2_ / z;
        const float sy = glm::dot(v, up_) * inv_half_height2_ / z;
        return on_film(sx, sy, z / glm::length(v), margin);
    }

    // The same seen from `lens` (a lens_point): the ray from it through p crosses the plane of
    // focus at the point the pinhole sees at the film position, and the importance is the
    // pinhole's for the direction lens -> p. Sampling the lens point uniformly, as the camera
    // rays do, the lens's area cancels: pbrt-v4's PerspectiveCamera::SampleWi divides We, which
    // has 1 / lens area, by the pdf of the lens point per solid angle, which has it too.
    std::optional<FilmPoint> film_point_through_lens(const glm::vec3& p, const glm::vec3& lens, float margin) const {
        const glm::vec3 v = p - lens;
        const float z = glm::dot(v, forward_);
        if (!(z > 0.0f)) return std::nullopt;
        const glm::vec3 on_focus_plane = lens + v * (focus_distance_ / z) - eye_;
        const float sx = glm::dot(on_focus_plane, right_) * inv_half_width2_ / focus_distance_;
        const float sy = glm::dot(on_focus_plane, up_) * inv_half_height2_ / focus_distance_;
        return on_film(sx, sy, z / glm::length(v), margin);
    }

private:
    std::optional<FilmPoint> on_film(float sx, float sy, float cos_theta, float margin) const {
        const float x = 0.5f * (sx + 1.0f) * width_, y = 0.5f * (1.0f - sy) * height_;
        if (!(x >= -margin && x < width_ + margin && y >= -margin && y < height_ + margin)) return std::nullopt;
        return FilmPoint{x, y, 1.0f / (pixel_area_ * cos_theta * cos_theta * cos_theta)};
    }

    glm::vec3 eye_{0.0f}, forward_{1, 0, 0}, right_{0, -1, 0}, up_{0, 0, 1};
    glm::vec3 unit_right_{0, -1, 0}, unit_up_{0, 0, 1};
    float width_ = 1.0f, height_ = 1.0f;
    float inv_half_width2_ = 1.0f, inv_half_height2_ = 1.0f, pixel_area_ = 4.0f;
    float lens_radius_ = 0.0f, focus_distance_ = 1.0f;
    bool orthographic_ = false;
};

}  // namespace wt
