#pragma once
// The room the oracle tests render and solve, and the two views of it.

#include "oracle/pinhole_view.h"
#include "oracle/room.h"

namespace wt::test {

// 1 x 1.25 x 0.75, a red and a green side wall, the rest shades of grey, a 0.25 x 0.25 light in
// the ceiling. The light's edges lie on every patch grid the tests solve on (h = 1/8 .. 1/32);
// every coordinate is exact in float, so the renderer's geometry is the oracle's.
inline oracle::Room oracle_room() {
    oracle::Room room;
    room.size = {1.0, 1.25, 0.75};
    room.albedo = {{{0.75, 0.25, 0.2},    // x = 0: red
                    {0.2, 0.65, 0.25},    // x = 1: green
                    {0.6, 0.6, 0.6},      // y = 0, behind the room view's camera
                    {0.7, 0.7, 0.65},     // y = 1.25, facing it
                    {0.5, 0.45, 0.4},     // floor
                    {0.75, 0.75, 0.75}}};  // ceiling
    room.light_lo = {0.375, 0.5, 0.0};
    room.light_hi = {0.625, 0.75, 0.0};
    room.light_radiance = {12.0, 11.0, 9.0};
    return room;
}

// From near the front wall, looking at the back: both side walls, the floor, the back wall, the
// ceiling and the light.
inline oracle::PinholeCamera oracle_room_view() {
    oracle::PinholeCamera c;
    c.eye = {0.5, 0.08, 0.3};
    c.look_at = {0.5, 1.25, 0.45};
    c.fov_degrees = 90.0;
    c.width = 32;
    c.height = 24;
    return c;
}

// From the floor, straight up: the ceiling around the light fills the picture. The ceiling is
// lit only indirectly (the light is in its plane), so this view sees indirect light alone.
inline oracle::PinholeCamera oracle_ceiling_view() {
    oracle::PinholeCamera c;
    c.eye = {0.5, 0.625, 0.02};
    c.look_at = {0.5, 0.625, 0.75};
    c.up = {0.0, 1.0, 0.0};
    c.fov_degrees = 76.0;
    c.width = 24;
    c.height = 30;
    return c;
}

}  // namespace wt::test
