#pragma once
// The one entry to the mesh-file formats: the extension picks the reader.

#include <string>

#include "core/import/imported_mesh.h"

namespace wt {

// .obj (with its .mtl files), .ply (ASCII or binary, either endianness), .gltf (+ .bin) or .glb,
// case-insensitive. Throws MeshFileError naming `path` (and the line, byte or accessor where the
// format allows) for an unreadable or malformed file, an index out of range, a NaN or infinite
// coordinate, a face with fewer than 3 vertices, or a file without a triangle.
// What the scene will use of the file, so that nothing else is read.
struct MeshFileUse {
    // The file's own materials ("material": "from_file"): the images their textures name are
    // read (an error if they cannot be). Without, the file's textures are not touched.
    bool file_materials = true;
    // A textured material of the scene's: the texture coordinates are kept (an OBJ vertex split
    // per coordinate its corners give it). Without, they are kept only for textured file materials.
    bool texture_coordinates = false;
};
ImportedMesh read_mesh_file(const std::string& path, MeshFileUse use = {});

// The file's extension in lower case, with its dot (".glb").
std::string lower_extension(const std::string& path);
// Throws MeshFileError (errno's words) unless `path` is a regular file within the mesh-file
// limit: a FIFO or device (/dev/zero) is refused before a reader could block on it.
void check_readable_mesh_file(const std::string& path);

// The first line of a library's message, which is often several lines of which the first says it.
std::string first_line(const std::string& text);

// The format readers, each in its own file; read_mesh_file() checks what is common to all.
ImportedMesh read_obj_file(const std::string& path, MeshFileUse use);
ImportedMesh read_ply_file(const std::string& path, MeshFileUse use);
ImportedMesh read_gltf_file(const std::string& path, MeshFileUse use);

}  // namespace wt
