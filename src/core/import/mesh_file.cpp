#include "core/import/mesh_file.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "core/system/regular_file.h"

namespace wt {

std::string lower_extension(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return ext;
}

// The libraries' own messages for a missing file vary ("Cannot open file [x]", "File not found");
// errno says why in the same words for every format.
void check_readable_mesh_file(const std::string& path) {
    try {
        open_regular_file(path, kMaxMeshFileBytes);
    } catch (const InputFileError& e) {
        throw MeshFileError(e.what());
    }
}

std::string first_line(const std::string& text) {
    std::string s = text.substr(0, text.find('\n'));
    while (!s.empty() && (s.back() == '\r' || s.back() == ' ')) s.pop_back();
    return s;
}

ImportedMesh read_mesh_file(const std::string& path, MeshFileUse use) {
    const std::string ext = lower_extension(path);
    ImportedMesh (*reader)(const std::string&, MeshFileUse) = nullptr;
    if (ext == ".obj") reader = read_obj_file;
    else if (ext == ".ply") reader = read_ply_file;
    else if (ext == ".gltf" || ext == ".glb") reader = read_gltf_file;
    else
        throw MeshFileError(path + ": unknown mesh file extension \"" + ext + "\" (allowed: .obj, .ply, .gltf, .glb)");
    check_readable_mesh_file(path);
    ImportedMesh mesh = reader(path, use);
    if (mesh.triangles.empty()) throw MeshFileError(path + ": the file has no triangles (an empty mesh)");
    if (mesh.positions.size() > UINT32_MAX)
        throw MeshFileError(path + ": " + std::to_string(mesh.positions.size()) +
                            " vertices, more than 2^32 - 1 (the renderer's indices are 32-bit)");
    return mesh;
}

}  // namespace wt
