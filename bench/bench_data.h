#pragma once
// The benchmark meshes as files, and the scenes that load them: what make_displaced_sphere
// (the bench_data target) writes into build/bench-data/ and bench_scene.cpp reads back through
// the scene loader's mesh_file shape.

#include <string>

#include "displaced_sphere.h"

namespace wt::bench {

// The scene file of benchmark mesh `mesh` in `directory`: DIRECTORY/hexroom_NAME.json.
std::string bench_scene_file(const std::string& directory, const BenchmarkMesh& mesh);

// The scene file of the hexroom with kBenchmarkInstances copies of the mesh placed in it by
// instances: DIRECTORY/hexroom_NAME_instances.json.
std::string bench_instanced_scene_file(const std::string& directory, const BenchmarkMesh& mesh);
// Copies of the mesh in that scene, each scaled by kBenchmarkInstanceScale about the mesh's
// centre (a ball of radius about 1) and moved to its own place in the room's air.
constexpr int kBenchmarkInstances = 8;
constexpr float kBenchmarkInstanceScale = 0.45f;

// Writes into `directory` (which must exist) the mesh as NAME.ply (binary little-endian, with
// normals), NAME.obj (with vn) and NAME.glb, the same vertices, normals and triangles in the
// same order, bench_scene_file(directory, mesh): scenes/hexroom.json plus the material
// NAME (added_mesh_material) and {"type": "mesh_file", "file": "NAME.ply", "material": NAME},
// and bench_instanced_scene_file(directory, mesh): the same with the mesh_file under "meshes"
// and an instance shape placing it kBenchmarkInstances times.
// Throws std::runtime_error naming the file that could not be written.
void write_bench_data(const std::string& directory, const BenchmarkMesh& mesh);

}  // namespace wt::bench
