// libFuzzer target, compiled once per mesh format (WT_FUZZ_EXTENSION: ".obj", ".ply", ".glb"):
// the input written to a file of that extension and read through read_mesh_file, then placed
// with computed smooth normals, as a mesh_file shape is. Anything but a MeshFileError is a
// finding.

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>

#include <glm/mat4x4.hpp>

#include "core/import/imported_mesh.h"
#include "core/import/mesh_file.h"
#include "core/import/place_mesh.h"

#ifndef WT_FUZZ_EXTENSION
#error "define WT_FUZZ_EXTENSION as the mesh file extension, e.g. \".ply\""
#endif

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
    // One file per process, rewritten for every input (the readers take a path).
    static const std::string path = "/tmp/wavetrace-fuzz-" + std::to_string(getpid()) + WT_FUZZ_EXTENSION;
    std::FILE* file = std::fopen(path.c_str(), "wb");
    if (!file) return 0;
    std::fwrite(data, 1, size, file);
    std::fclose(file);
    try {
        wt::ImportedMesh mesh = wt::read_mesh_file(path);
        wt::place_mesh(mesh, glm::dmat4(1.0), wt::NormalsMode::smooth);
    } catch (const wt::MeshFileError&) {
    }
    return 0;
}
