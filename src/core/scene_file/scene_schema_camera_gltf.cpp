#include <cmath>
#include <cstdio>

#include "core/camera/camera.h"
#include "core/import/gltf_camera.h"
#include "core/scene_file/scene_schema.h"

// "camera": {"gltf": FILE, "name": NAME} (or "index": N): the camera of a glTF file, placed by
// its node (core/import/gltf_camera.h), then by an optional "transform" as a mesh_file's; the
// thin lens's keys as for any perspective camera.

namespace wt {

namespace {

// The keys the glTF camera gives, and what to do instead.
constexpr const char* kFromTheFile[] = {"eye", "look_at", "up", "fov_degrees", "projection", "width_world"};

std::string ratio(double r) {
    char text[32];
    std::snprintf(text, sizeof text, "%.4g", r);
    return text;
}

}  // namespace

CameraDescription read_gltf_camera_section(const Reader& in, const Json& j, const std::string& path,
                                           const RenderSettings& render, std::vector<std::string>& notes) {
    for (const char* key : kFromTheFile)
        if (in.optional(j, key))
            in.fail(member_path(path, key), "comes from the glTF camera; place the camera with \"transform\" instead");
    in.check_keys(j, path, {"gltf", "name", "index", "transform", "aperture_radius", "focus_distance", "focus_on"},
                  " for a glTF camera");
    const std::string file_path = member_path(path, "gltf");
    const std::string file = in.text(in.required(j, "gltf", path), file_path);
    if (file.empty()) in.fail(file_path, "must not be empty");
    const std::string resolved = in.resolve(file);

    GltfCameraPick pick;
    const Json* name = in.optional(j, "name");
    const Json* index = in.optional(j, "index");
    if (name && index) in.fail(member_path(path, "index"), "cannot be given with name; give one");
    if (!name && !index) in.fail(path, "a glTF camera needs \"name\" or \"index\" to say which of the file's cameras");
    const std::string pick_path = member_path(path, name ? "name" : "index");
    if (name) pick.name = in.text(*name, pick_path);
    else pick.index = int64_t(in.integer(*index, pick_path, 0, INT32_MAX));
    if (const Json* t = in.optional(j, "transform")) pick.transform = read_transform(in, *t, member_path(path, "transform"));

    GltfCamera loaded;
    try {
        loaded = read_gltf_camera(resolved, pick);
    } catch (const GltfCameraPickError& e) {
        in.fail(pick_path, e.what());
    } catch (const MeshFileError& e) {
        in.fail(file_path, e.what());
    }
    CameraDescription camera = loaded.camera;
    // The renderer builds the basis in float (as read_camera checks for a camera written out).
    const CameraBasis basis = camera_basis(camera);
    if (!is_unit_in_float(basis.forward) || !is_unit_in_float(basis.right) || !is_unit_in_float(basis.up))
        in.fail(pick_path, loaded.label + ": its placement (eye " + format_vec3(camera.eye) +
                               ") cannot be turned into a camera basis in 32-bit float");

    const std::string note = in.source() + ": " + pick_path + ": ";
    for (const std::string& n : loaded.notes) notes.push_back(note + n);
    const double image_ratio = double(render.width) / double(render.height);
    if (loaded.aspect_ratio > 0.0 && std::fabs(loaded.aspect_ratio / image_ratio - 1.0) > 1e-3)
        notes.push_back(note + loaded.label + ": made for an aspect ratio of " + ratio(loaded.aspect_ratio) +
                        "; the image's " + std::to_string(render.width) + "x" + std::to_string(render.height) + " (" +
                        ratio(image_ratio) + ") is used, " +
                        (camera.projection == Projection::perspective ? "the vertical field of view kept"
                                                                      : "the width (xmag) kept"));

    if (camera.projection == Projection::orthographic) {
        for (const char* key : {"aperture_radius", "focus_distance", "focus_on"})
            if (in.optional(j, key))
                in.fail(member_path(path, key), "is for a perspective camera; " + loaded.label + " is orthographic");
        return camera;
    }
    read_thin_lens(in, j, path, camera);
    // The file's camera has no focus: the distance to look_at would be an arbitrary one.
    if (camera.aperture_radius > 0.0f && camera.focus_distance == 0.0f)
        in.fail(member_path(path, "aperture_radius"), "needs focus_distance or focus_on with a glTF camera (glTF "
                                                      "cameras have no focus distance)");
    return camera;
}

}  // namespace wt
