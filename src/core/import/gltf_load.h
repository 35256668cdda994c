#pragma once
// Reading a glTF 2.0 file (.gltf with its .bin files, or .glb) into tinygltf's model, once for
// every use of it: the meshes, lights and materials (gltf_import.cpp) and the cameras
// (gltf_camera.h) read the same model, parsed and checked the same way.

#include <string>

#include <tiny_gltf.h>

namespace wt {

// Parses `path` (a .glb is recognised by its content, not its extension), with the buffers and
// images it references read relative to its directory (images kept encoded: gltf_textures.h
// decodes what is used), and refuses glTF 1.0 and required extensions we do not read
// (gltf_version.h). Throws MeshFileError naming `path`.
tinygltf::Model load_gltf_model(const std::string& path);

}  // namespace wt
