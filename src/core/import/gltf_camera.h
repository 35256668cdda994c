#pragma once
// A scene's camera taken from a glTF 2.0 file (glTF 2.0, 3.10): one of the file's cameras,
// picked by name or index, placed by the node that names it. glTF cameras look down their
// node's local -Z with +Y up and +X to the right (3.10.1); a perspective camera's yfov is our
// vertical field of view and an orthographic one's xmag half our width_world.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>

#include "core/description/scene_description.h"
#include "core/import/imported_mesh.h"

namespace wt {

// Which camera: by index into the file's cameras, or by name, which is a camera's name, or
// else the name of the node that places one (Blender names the object and the camera apart;
// a node's name also says which of several nodes placing one camera is meant).
struct GltfCameraPick {
    std::optional<std::string> name;
    std::optional<int64_t> index;
    glm::dmat4 transform{1.0};  // the scene's transform, applied after the file's nodes'
};

struct GltfCamera {
    // eye, look_at (on the view axis, a power of two at least max(1, |eye|) ahead, so that
    // look_at - eye keeps the direction in float), up, the projection and fov_degrees or
    // width_world. The thin lens is the scene file's to add.
    CameraDescription camera;
    int index = -1;     // into the file's cameras
    int node = -1;      // the node that places it
    std::string label;  // "camera 1 (\"Side\")", for messages
    // The width / height the file's camera was made for (perspective aspectRatio, or
    // xmag / ymag); 0 if it does not say. Informational: the image's size rules.
    double aspect_ratio = 0.0;
    std::vector<std::string> notes;
};

// What is wrong with the picked camera rather than with the file (an unknown name, an index
// out of range, no node or several nodes placing it, a degenerate transform, a bad yfov or xmag).
struct GltfCameraPickError : MeshFileError {
    using MeshFileError::MeshFileError;
};

// Reads `path` (load_gltf_model) and places the picked camera by its node's world transform
// (gltf_nodes.h) and then `pick.transform`. Throws MeshFileError naming `path` for a file that
// cannot be read or has no cameras, GltfCameraPickError (naming `path` and the camera) for the
// rest. A camera that two nodes place, or one node reached along two paths, is refused: which
// place is meant is not the renderer's to guess (pick the node by its name instead). znear and
// zfar are not read: a path tracer's rays start at the eye (or the lens) and are never clipped.
GltfCamera read_gltf_camera(const std::string& path, const GltfCameraPick& pick);

}  // namespace wt
