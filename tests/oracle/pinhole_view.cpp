#include "oracle/pinhole_view.h"

#include <cmath>
#include <limits>

namespace oracle {

Vec3 camera_direction(const PinholeCamera& camera, double film_x, double film_y) {
    constexpr double kPi = 3.14159265358979323846;
    const Vec3 forward = normalize(camera.look_at - camera.eye);
    const Vec3 right = normalize(cross(forward, camera.up));
    const Vec3 up = cross(right, forward);
    const double half_height = std::tan(0.5 * camera.fov_degrees * kPi / 180.0);
    const double half_width = half_height * camera.width / camera.height;
    const double sx = 2.0 * film_x / camera.width - 1.0;
    const double sy = 1.0 - 2.0 * film_y / camera.height;
    return normalize(forward + (sx * half_width) * right + (sy * half_height) * up);
}

WallPoint leave_room(const Room& room, const Vec3& origin, const Vec3& direction) {
    WallPoint nearest;
    double t_nearest = std::numeric_limits<double>::infinity();
    for (int axis = 0; axis < 3; ++axis) {
        if (direction[axis] == 0.0) continue;
        const int side = direction[axis] > 0.0 ? 1 : 0;
        const double plane = side == 1 ? room.size[axis] : 0.0;
        const double t = (plane - origin[axis]) / direction[axis];
        if (t < t_nearest) {
            t_nearest = t;
            nearest.wall = 2 * axis + side;
        }
    }
    nearest.point = origin + t_nearest * direction;
    // On its own wall's plane exactly, not a rounding error off it.
    const int axis = wall_axis(nearest.wall);
    nearest.point[axis] = wall_side(nearest.wall) == 1 ? room.size[axis] : 0.0;
    return nearest;
}

}  // namespace oracle
