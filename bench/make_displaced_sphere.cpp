// make_displaced_sphere OUTPUT_DIR [MESH...]
//
// Writes the benchmark meshes (displaced_sphere.h: mesh10k, mesh100k, mesh1m, or the ones
// named) into OUTPUT_DIR, creating it if needed, each as
//   MESH.ply           binary little-endian PLY with vertex normals
//   MESH.obj           OBJ with vn
//   MESH.glb           glTF 2.0 binary: POSITION, NORMAL, uint32 indices
//   hexroom_MESH.json  scenes/hexroom.json plus the material MESH (added_mesh_material) and
//                      the shape {"type": "mesh_file", "file": "MESH.ply", "material": "MESH"}:
//                      the scene bench_scene.h builds in code as hexroom_MESH
// The three mesh files hold the same vertices, normals and triangles in the same order, so an
// importer of any of them must give the same TriangleMesh. `cmake --build build --target
// bench_data` runs this into build/bench-data.
//
// Exit status 0 on success, 1 if a file cannot be written, 2 for bad arguments.

#include <charconv>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "atomic_file.h"
#include "bench_scene.h"
#include "displaced_sphere.h"
#include "mesh_writers.h"

namespace {

using namespace wt;
using namespace wt::bench;
using json = nlohmann::ordered_json;

// The double with the float's shortest decimal, so 0.8f is written 0.8, not 0.800000011920929.
double shortest_double(float value) {
    char digits[32];
    const auto end = std::to_chars(digits, digits + sizeof digits, value).ptr;
    return std::stod(std::string(digits, end));
}

json colour(const glm::vec3& c) { return {shortest_double(c.x), shortest_double(c.y), shortest_double(c.z)}; }

json hexroom_json() {
    const std::string path = std::string(WT_SCENES_DIR) + "/hexroom.json";
    std::ifstream in(path);
    if (!in) throw std::runtime_error(path + ": cannot read");
    return json::parse(in);
}

// The scene with one material or shape per line, as scenes/hexroom.json is laid out, rather
// than one number per line.
std::string scene_text(const json& scene) {
    std::string text = "{\n";
    for (auto item = scene.begin(); item != scene.end(); ++item) {
        text += "  \"" + item.key() + "\": ";
        const json& value = item.value();
        const bool one_per_line = (value.is_object() && item.key() == "materials") || value.is_array();
        if (!one_per_line) {
            text += value.dump();
        } else {
            text += value.is_object() ? "{\n" : "[\n";
            for (auto entry = value.begin(); entry != value.end(); ++entry) {
                text += "    ";
                if (value.is_object()) text += "\"" + entry.key() + "\": ";
                text += entry.value().dump() + (std::next(entry) == value.end() ? "\n" : ",\n");
            }
            text += value.is_object() ? "  }" : "  ]";
        }
        text += std::next(item) == scene.end() ? "\n" : ",\n";
    }
    return text + "}\n";
}

void write_scene(const std::string& path, const BenchmarkMesh& mesh) {
    json scene = hexroom_json();
    const Material material = added_mesh_material(mesh.name);
    scene["materials"][mesh.name] = {{"type", "lambertian"}, {"albedo", colour(material.albedo)}};
    scene["shapes"].push_back({{"type", "mesh_file"}, {"file", std::string(mesh.name) + ".ply"}, {"material", mesh.name}});
    write_file_atomically(path, [&](std::ostream& out) { out << scene_text(scene); });
}

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
            const DisplacedSphereShape shape = benchmark_sphere(mesh->segments_u, mesh->segments_v);
            const TriangleMesh triangles = displaced_sphere(shape, 0);
            const std::string stem = (directory / mesh->name).string();
            const std::string comment = std::string("wavetrace bench ") + mesh->name + ": displaced UV sphere, " +
                                        std::to_string(shape.segments_u) + " x " + std::to_string(shape.segments_v) +
                                        " segments (bench/displaced_sphere.h)";
            write_ply(stem + ".ply", triangles, comment);
            write_obj(stem + ".obj", triangles, comment);
            write_glb(stem + ".glb", triangles, comment);
            write_scene((directory / ("hexroom_" + std::string(mesh->name) + ".json")).string(), *mesh);
            std::printf("make_displaced_sphere: %s: %zu triangles, %zu vertices -> %s.{ply,obj,glb}, hexroom_%s.json\n", mesh->name,
                        triangles.triangles.size(), triangles.vertices.size(), stem.c_str(), mesh->name);
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "make_displaced_sphere: %s\n", e.what());
        return 1;
    }
    return 0;
}
