#pragma once
// The benchmark meshes as files, and the scenes that load them: what make_displaced_sphere
// (the bench_data target) writes into build/bench-data/ and bench_scene.cpp reads back through
// the scene loader's mesh_file shape.

#include <string>

#include "displaced_sphere.h"

namespace wt::bench {

// The scene file of benchmark mesh `mesh` in `directory`: DIRECTORY/hexroom_NAME.json.
std::string bench_scene_file(const std::string& directory, const BenchmarkMesh& mesh);

// Writes into `directory` (which must exist) the mesh as NAME.ply (binary little-endian, with
// normals), NAME.obj (with vn) and NAME.glb, the same vertices, normals and triangles in the
// same order, and bench_scene_file(directory, mesh): scenes/hexroom.json plus the material
// NAME (added_mesh_material) and {"type": "mesh_file", "file": "NAME.ply", "material": NAME}.
// Throws std::runtime_error naming the file that could not be written.
void write_bench_data(const std::string& directory, const BenchmarkMesh& mesh);

}  // namespace wt::bench
