#pragma once
// What a pinhole camera inside the room sees, by the oracle's own ray casting. The camera is
// the one README's scene format describes ("camera"): `fov_degrees` is the vertical field of
// view, the horizontal follows from the aspect ratio, screen right is cross(look_at - eye, up);
// pixel (x, y) covers the film square [x, x + 1) x [y, y + 1), y counted downwards.

#include <optional>

#include "oracle/room.h"
#include "oracle/vec3.h"

namespace oracle {

struct PinholeCamera {
    Vec3 eye, look_at, up{0.0, 0.0, 1.0};
    double fov_degrees = 90.0;
    int width = 32, height = 32;
};

// The direction through film position (film_x, film_y), unit length.
Vec3 camera_direction(const PinholeCamera& camera, double film_x, double film_y);

struct WallPoint {
    int wall = 0;
    Vec3 point;
};

// Where a ray from `origin` (strictly inside the room) along `direction` leaves the room: the
// nearest of the three walls its direction points at.
WallPoint leave_room(const Room& room, const Vec3& origin, const Vec3& direction);

// What film position (film_x, film_y) sees.
inline WallPoint seen_at(const Room& room, const PinholeCamera& camera, double film_x, double film_y) {
    return leave_room(room, camera.eye, camera_direction(camera, film_x, film_y));
}

}  // namespace oracle
