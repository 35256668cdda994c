#pragma once
// The oracle's room (tests/oracle) as a scene file for the renderer: the same box, walls and
// light, written as JSON and loaded through the scene loader like any user's scene, so a
// failing comparison can be replayed with the command line (oracle_comparison.h prints it).

#include <fstream>
#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>

#include "oracle/pinhole_view.h"
#include "oracle/room.h"

namespace wt::test {

struct OracleRender {
    int spp = 64;
    uint64_t seed = 1;
    int max_bounces = 64;
};

inline nlohmann::json json_vec(const oracle::Vec3& v) { return nlohmann::json::array({v.x, v.y, v.z}); }

// A rectangle in the plane coordinate[axis] = plane, [lo, hi] along the other two axes, as a
// quad; `front_towards` the sign of the axis its front face (cross(v1 - v0, v2 - v0)) points to.
inline nlohmann::json quad(int axis, double plane, oracle::Vec3 lo, oracle::Vec3 hi, int front_towards) {
    const int a = (axis + 1) % 3, b = (axis + 2) % 3;  // e_a x e_b = +e_axis
    oracle::Vec3 v[4] = {lo, lo, lo, lo};
    for (oracle::Vec3& c : v) c[axis] = plane;
    v[1][a] = hi[a];
    v[2][a] = hi[a];
    v[2][b] = hi[b];
    v[3][b] = hi[b];
    if (front_towards < 0) std::swap(v[1], v[3]);
    return {{"type", "quad"}, {"vertices", {json_vec(v[0]), json_vec(v[1]), json_vec(v[2]), json_vec(v[3])}}};
}

inline nlohmann::json scene_json(const oracle::Room& room, const oracle::PinholeCamera& camera, const OracleRender& r) {
    nlohmann::json scene;
    scene["camera"] = {{"eye", json_vec(camera.eye)}, {"look_at", json_vec(camera.look_at)}, {"up", json_vec(camera.up)},
                       {"fov_degrees", camera.fov_degrees}};
    scene["render"] = {{"width", camera.width}, {"height", camera.height}, {"spp", r.spp}, {"seed", r.seed},
                       {"max_bounces", r.max_bounces}};
    nlohmann::json materials, shapes = nlohmann::json::array();
    for (int w = 0; w < oracle::kWalls; ++w) {
        const std::string name = "wall" + std::to_string(w);
        const oracle::Rgb& a = room.albedo[w];
        materials[name] = {{"type", "lambertian"}, {"albedo", {a[0], a[1], a[2]}}};
        const int axis = oracle::wall_axis(w);
        const double plane = oracle::wall_side(w) == 0 ? 0.0 : room.size[axis];
        const oracle::Vec3 zero{0.0, 0.0, 0.0};
        if (w != oracle::kCeiling) {
            shapes.push_back(quad(axis, plane, zero, room.size, oracle::wall_normal_sign(w)));
            shapes.back()["material"] = name;
            continue;
        }
        // The ceiling around the light: four rectangles meeting it edge to edge.
        const oracle::Vec3& lo = room.light_lo;
        const oracle::Vec3& hi = room.light_hi;
        const oracle::Vec3 s = room.size;
        for (const auto& [from, to] : {std::pair{zero, oracle::Vec3{s.x, lo.y, 0}}, std::pair{oracle::Vec3{0, hi.y, 0}, s},
                                       std::pair{oracle::Vec3{0, lo.y, 0}, oracle::Vec3{lo.x, hi.y, 0}},
                                       std::pair{oracle::Vec3{hi.x, lo.y, 0}, oracle::Vec3{s.x, hi.y, 0}}}) {
            shapes.push_back(quad(axis, plane, from, to, -1));
            shapes.back()["material"] = name;
        }
    }
    const oracle::Rgb& le = room.light_radiance;
    materials["light"] = {{"type", "lambertian"}, {"albedo", {0.0, 0.0, 0.0}}, {"emission", {le[0], le[1], le[2]}}};
    // Its front face down, into the room: lights emit from the front only.
    shapes.push_back(quad(2, room.size.z, room.light_lo, room.light_hi, -1));
    shapes.back()["material"] = "light";
    scene["materials"] = materials;
    scene["shapes"] = shapes;
    return scene;
}

// Writes the scene to `path` (replaced), for the loader and for whoever replays a failure.
inline void write_scene_file(const std::string& path, const nlohmann::json& scene) {
    std::ofstream out(path);
    out << scene.dump(2) << "\n";
    if (!out) throw std::runtime_error(path + ": cannot write the oracle's scene file");
}

}  // namespace wt::test
