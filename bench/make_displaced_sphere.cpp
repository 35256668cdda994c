// make_displaced_sphere OUTPUT_DIR [MESH...]
//
// Writes the benchmark meshes (displaced_sphere.h: mesh10k, mesh100k, mesh1m, or the ones
// named) into OUTPUT_DIR, creating it if needed (bench_data.h), each as
//   MESH.ply           binary little-endian PLY with vertex normals
//   MESH.obj           OBJ with vn
//   MESH.glb           glTF 2.0 binary: POSITION, NORMAL, uint32 indices
//   hexroom_MESH.json  scenes/hexroom.json plus the material MESH (added_mesh_material) and
//                      the shape {"type": "mesh_file", "file": "MESH.ply", "material": "MESH"}:
//                      the scene bench_intersect measures as hexroom_MESH
// The three mesh files hold the same vertices, normals and triangles in the same order, so an
// importer of any of them must give the same TriangleMesh. `cmake --build build --target
// bench_data` runs this into build/bench-data.
//
// Exit status 0 on success, 1 if a file cannot be written, 2 for bad arguments.

#include <cstdio>
#include <exception>
#include <filesystem>
#include <string>
#include <vector>

#include "bench_data.h"
#include "displaced_sphere.h"

namespace {

using namespace wt;
using namespace wt::bench;

const BenchmarkMesh* mesh_named(const std::string& name) {
    for (const BenchmarkMesh& mesh : kBenchmarkMeshes)
        if (name == mesh.name) return &mesh;
    return nullptr;
}

int usage(const char* problem) {
    std::fprintf(stderr, "make_displaced_sphere: %s\nusage: make_displaced_sphere OUTPUT_DIR [", problem);
    for (const BenchmarkMesh& mesh : kBenchmarkMeshes) std::fprintf(stderr, "%s%s", mesh.name, &mesh == &kBenchmarkMeshes[2] ? "" : "|");
    std::fprintf(stderr, "]...\n");
    return 2;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) return usage("missing OUTPUT_DIR");
    const std::filesystem::path directory = argv[1];
    std::vector<const BenchmarkMesh*> meshes;
    for (int i = 2; i < argc; ++i) {
        const BenchmarkMesh* mesh = mesh_named(argv[i]);
        if (!mesh) return usage((std::string("no benchmark mesh named '") + argv[i] + "'").c_str());
        meshes.push_back(mesh);
    }
    if (meshes.empty())
        for (const BenchmarkMesh& mesh : kBenchmarkMeshes) meshes.push_back(&mesh);

    try {
        std::filesystem::create_directories(directory);
        for (const BenchmarkMesh* mesh : meshes) {
            write_bench_data(directory.string(), *mesh);
            std::printf("make_displaced_sphere: %s: %zu triangles -> %s/%s.{ply,obj,glb}, %s\n", mesh->name,
                        displaced_sphere_triangle_count(benchmark_sphere(mesh->segments_u, mesh->segments_v)),
                        directory.string().c_str(), mesh->name, bench_scene_file(directory.string(), *mesh).c_str());
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "make_displaced_sphere: %s\n", e.what());
        return 1;
    }
    return 0;
}
