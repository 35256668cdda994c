#pragma once
// The room the oracle solves: the box [0, size.x] x [0, size.y] x [0, size.z] (z up), seen from
// inside, every wall Lambertian with its own albedo, and one rectangular area light set into the
// ceiling, emitting downwards and reflecting nothing (albedo 0, like the hexroom's light).
// The oracle's own description, in double; tests/oracle_test.cpp turns it into a scene file
// for the renderer.

#include <array>

#include "oracle/vec3.h"

namespace oracle {

using Rgb = std::array<double, 3>;

// The six walls, numbered 2 * axis + side: wall 2a lies in the plane coordinate[a] = 0, wall
// 2a + 1 in coordinate[a] = size[a]. Wall 5 is the ceiling (z = size.z), wall 4 the floor.
constexpr int kWalls = 6;
constexpr int kCeiling = 5;
inline int wall_axis(int wall) { return wall / 2; }
inline int wall_side(int wall) { return wall % 2; }
// The two axes in the wall's plane, the smaller first.
inline std::array<int, 2> wall_plane_axes(int wall) {
    const int u = wall_axis(wall);
    return u == 0 ? std::array<int, 2>{1, 2} : u == 1 ? std::array<int, 2>{0, 2} : std::array<int, 2>{0, 1};
}
// +1 when the wall's inward normal is +e_axis (the wall at 0), -1 for the wall at size[axis].
inline int wall_normal_sign(int wall) { return wall_side(wall) == 0 ? 1 : -1; }

struct Room {
    Vec3 size{1.0, 1.0, 1.0};
    std::array<Rgb, kWalls> albedo{};  // per wall, each channel in [0, 1)
    // The light: [light_lo.x, light_hi.x] x [light_lo.y, light_hi.y] in the ceiling (z of both
    // ignored), radiance light_radiance towards -z.
    Vec3 light_lo, light_hi;
    Rgb light_radiance{};

    bool in_light(const Vec3& p_on_ceiling) const {
        return p_on_ceiling.x > light_lo.x && p_on_ceiling.x < light_hi.x && p_on_ceiling.y > light_lo.y &&
               p_on_ceiling.y < light_hi.y;
    }
};

}  // namespace oracle
