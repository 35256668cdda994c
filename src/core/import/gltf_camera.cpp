#include "core/import/gltf_camera.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <tiny_gltf.h>

#include "core/import/gltf_load.h"
#include "core/import/gltf_nodes.h"
#include "core/import/mesh_file.h"

namespace wt {

namespace {

constexpr double kPiDouble = 3.14159265358979323846;

std::string quoted(const std::string& s) { return "\"" + s + "\""; }

std::string camera_label(const tinygltf::Model& model, int index) {
    const std::string& name = model.cameras[std::size_t(index)].name;
    return "camera " + std::to_string(index) + (name.empty() ? "" : " (" + quoted(name) + ")");
}

std::string number(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.9g", v);
    return text;
}

// The picked camera, and the node it must be placed by when the name was a node's (else -1).
struct Picked {
    int camera, node;
};

Picked pick_camera(const std::string& path, const tinygltf::Model& model, const GltfCameraPick& pick) {
    const auto fail = [&](const std::string& what) -> Picked { throw GltfCameraPickError(path + ": " + what); };
    const int64_t count = int64_t(model.cameras.size());
    if (pick.index) {
        if (*pick.index < 0 || *pick.index >= count)
            fail("camera index " + std::to_string(*pick.index) + " is out of range (the file has " + std::to_string(count) +
                 (count == 1 ? " camera)" : " cameras)"));
        return {int(*pick.index), -1};
    }
    std::vector<int> cameras, nodes;
    for (int i = 0; i < count; ++i)
        if (model.cameras[std::size_t(i)].name == *pick.name) cameras.push_back(i);
    if (cameras.size() > 1)
        fail(std::to_string(cameras.size()) + " cameras are named " + quoted(*pick.name) + " (" +
             camera_label(model, cameras[0]) + ", " + camera_label(model, cameras[1]) + "...): pick one by \"index\"");
    if (cameras.size() == 1) return {cameras[0], -1};
    for (std::size_t n = 0; n < model.nodes.size(); ++n)
        if (model.nodes[n].camera >= 0 && model.nodes[n].name == *pick.name) nodes.push_back(int(n));
    if (nodes.size() > 1)
        fail(std::to_string(nodes.size()) + " nodes placing a camera are named " + quoted(*pick.name) + " (nodes " +
             std::to_string(nodes[0]) + ", " + std::to_string(nodes[1]) + "...): pick the camera by \"index\"");
    if (nodes.empty()) {
        std::string names;
        for (int i = 0; i < count && i < 8; ++i)
            names += (i ? ", " : "") + (model.cameras[std::size_t(i)].name.empty() ? "camera " + std::to_string(i)
                                                                                     : quoted(model.cameras[std::size_t(i)].name));
        fail("no camera (or node placing one) is named " + quoted(*pick.name) + " (cameras: " + names +
             (count > 8 ? ", ..." : "") + ")");
    }
    const int camera = model.nodes[std::size_t(nodes[0])].camera;
    if (camera >= count) fail("node " + std::to_string(nodes[0]) + ": camera " + std::to_string(camera) + " does not exist");
    return {camera, nodes[0]};
}

// The projection: yfov as the vertical field of view, or xmag as half the width.
void read_projection(const tinygltf::Camera& c, GltfCamera& out) {
    const auto fail = [&](const std::string& what) { throw GltfCameraPickError(out.label + ": " + what); };
    if (c.type == "perspective") {
        const double yfov = c.perspective.yfov;
        const float degrees = float(yfov * 180.0 / kPiDouble);
        if (!(std::isfinite(yfov) && degrees > 0.0f && degrees < 180.0f))
            fail("perspective.yfov must be greater than 0 and less than pi radians (180 degrees), got " + number(yfov));
        out.camera.projection = Projection::perspective;
        out.camera.fov_degrees = degrees;
        if (std::isfinite(c.perspective.aspectRatio) && c.perspective.aspectRatio > 0.0) out.aspect_ratio = c.perspective.aspectRatio;
        return;
    }
    if (c.type == "orthographic") {
        const double xmag = c.orthographic.xmag, ymag = c.orthographic.ymag;
        const float width = float(2.0 * xmag);
        if (!(std::isfinite(width) && width > 0.0f))
            fail("orthographic.xmag must be finite and greater than 0, got " + number(xmag));
        if (!(std::isfinite(ymag) && ymag > 0.0))
            fail("orthographic.ymag must be finite and greater than 0, got " + number(ymag));
        out.camera.projection = Projection::orthographic;
        out.camera.width_world = width;
        out.aspect_ratio = xmag / ymag;
        return;
    }
    fail("type " + quoted(c.type) + " is not \"perspective\" or \"orthographic\"");
}

// The camera's frame from its world transform: eye at the origin, looking down -Z, +Y up.
void place(const glm::dmat4& world, int node, GltfCamera& out) {
    const auto fail = [&](const std::string& what) {
        throw GltfCameraPickError(out.label + ": node " + std::to_string(node) + "'s world transform " + what);
    };
    const glm::dmat3 linear(world);
    const double det = glm::determinant(linear);
    const double scale = glm::length(linear[0]) * glm::length(linear[1]) * glm::length(linear[2]);
    if (!std::isfinite(det) || !std::isfinite(scale) || !std::isfinite(world[3].x + world[3].y + world[3].z))
        fail("is not finite");
    if (!(std::fabs(det) > 1e-12 * scale))
        fail("is degenerate (its 3x3 part has determinant " + number(det) + ": a scale of 0?), so the camera has no direction");
    const glm::dvec3 eye(world[3]);
    const glm::dvec3 forward = glm::normalize(linear * glm::dvec3(0.0, 0.0, -1.0));
    const glm::dvec3 up = glm::normalize(linear * glm::dvec3(0.0, 1.0, 0.0));
    if (det < 0.0)
        out.notes.push_back(out.label + ": its placement (node " + std::to_string(node) +
                            "'s world transform, then the scene's) mirrors; the image is not mirrored: screen right "
                            "is cross(view direction, up)");
    // A power of two ahead, so look_at - eye is forward scaled exactly, up to look_at's rounding.
    const double ahead = std::exp2(std::ceil(std::log2(std::max(1.0, glm::length(eye)))));
    out.camera.eye = glm::vec3(eye);
    out.camera.look_at = glm::vec3(eye + ahead * forward);
    out.camera.up = glm::vec3(up);
}

}  // namespace

GltfCamera read_gltf_camera(const std::string& path, const GltfCameraPick& pick) {
    const std::string ext = lower_extension(path);
    if (ext != ".gltf" && ext != ".glb") throw MeshFileError(path + ": not a glTF file (a .gltf or .glb is, got \"" + ext + "\")");
    check_readable_mesh_file(path);
    const tinygltf::Model model = load_gltf_model(path);
    if (model.cameras.empty()) throw MeshFileError(path + ": the file has no cameras");
    const Picked picked = pick_camera(path, model, pick);
    GltfCamera out;
    out.index = picked.camera;
    out.label = path + ": " + camera_label(model, picked.camera);

    // Every node of the scene that places it, with its world transform.
    std::vector<std::pair<int, glm::dmat4>> placements;
    walk_gltf_nodes(path, model, gltf_scene_roots(path, model), [&](int index, const tinygltf::Node& node, const glm::dmat4& world) {
        if (node.camera == picked.camera && (picked.node < 0 || picked.node == index)) placements.emplace_back(index, world);
    });
    if (placements.empty())
        throw GltfCameraPickError(out.label + ": no node of the file's scene places it, so it has no position");
    if (placements.size() > 1) {
        const bool same_node = placements[0].first == placements[1].first;
        throw GltfCameraPickError(out.label + ": placed " + std::to_string(placements.size()) + " times (nodes " +
                                  std::to_string(placements[0].first) + ", " + std::to_string(placements[1].first) +
                                  (placements.size() > 2 ? ", ..." : "") + ")" +
                                  (same_node ? ", its node reached through several parents" : "") +
                                  ": which place is meant is ambiguous" +
                                  (same_node ? "" : " (pick it by the name of its node)"));
    }
    out.node = placements[0].first;
    read_projection(model.cameras[std::size_t(picked.camera)], out);
    place(pick.transform * placements[0].second, out.node, out);
    return out;
}

}  // namespace wt
