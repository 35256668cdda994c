#include "bench_data.h"

#include <charconv>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>

#include "atomic_file.h"
#include "bench_scene.h"
#include "mesh_writers.h"

namespace wt::bench {

namespace {

using json = nlohmann::ordered_json;

// The double with the float's shortest decimal, so 0.8f is written 0.8, not 0.800000011920929.
double shortest_double(float value) {
    char digits[32];
    const auto end = std::to_chars(digits, digits + sizeof digits, value).ptr;
    return std::stod(std::string(digits, end));
}

json json_vec3(const glm::vec3& c) { return {shortest_double(c.x), shortest_double(c.y), shortest_double(c.z)}; }

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
    scene["materials"][mesh.name] = {{"type", "lambertian"}, {"albedo", json_vec3(material.albedo)}};
    scene["shapes"].push_back({{"type", "mesh_file"}, {"file", std::string(mesh.name) + ".ply"}, {"material", mesh.name}});
    write_file_atomically(path, [&](std::ostream& out) { out << scene_text(scene); });
}

// The hexroom with the mesh placed kBenchmarkInstances times, each copy its ball's worth of air
// clear of the room's walls, spheres and light.
void write_instanced_scene(const std::string& path, const BenchmarkMesh& mesh) {
    json scene = hexroom_json();
    const Material material = added_mesh_material(mesh.name);
    scene["materials"][mesh.name] = {{"type", "lambertian"}, {"albedo", json_vec3(material.albedo)}};
    scene["meshes"] = {{mesh.name, {{"type", "mesh_file"}, {"file", std::string(mesh.name) + ".ply"}, {"material", mesh.name}}}};
    const glm::vec3 places[kBenchmarkInstances] = {{3.0f, -3.5f, -3.5f}, {3.0f, 3.5f, -3.5f}, {5.0f, -4.0f, 2.0f},
                                                   {5.0f, 4.0f, 2.0f},   {9.0f, -3.0f, 2.5f}, {9.0f, 3.0f, 2.5f},
                                                   {11.5f, 0.0f, 1.0f},  {7.0f, 0.0f, 3.0f}};
    json transforms = json::array();
    for (const glm::vec3& place : places) {  // s x + t puts the centre c at s c + t = place
        const glm::vec3 t = place - kBenchmarkInstanceScale * kBenchmarkSphereCentre;
        transforms.push_back({{"scale", shortest_double(kBenchmarkInstanceScale)}, {"translate", json_vec3(t)}});
    }
    scene["shapes"].push_back({{"type", "instance"}, {"of", mesh.name}, {"transforms", transforms}});
    write_file_atomically(path, [&](std::ostream& out) { out << scene_text(scene); });
}

}  // namespace

std::string bench_instanced_scene_file(const std::string& directory, const BenchmarkMesh& mesh) {
    return (std::filesystem::path(directory) / ("hexroom_" + std::string(mesh.name) + "_instances.json")).string();
}

std::string bench_scene_file(const std::string& directory, const BenchmarkMesh& mesh) {
    return (std::filesystem::path(directory) / ("hexroom_" + std::string(mesh.name) + ".json")).string();
}

void write_bench_data(const std::string& directory, const BenchmarkMesh& mesh) {
    const DisplacedSphereShape shape = benchmark_sphere(mesh.segments_u, mesh.segments_v);
    const TriangleMesh triangles = displaced_sphere(shape, 0);
    const std::string stem = (std::filesystem::path(directory) / mesh.name).string();
    const std::string comment = std::string("wavetrace bench ") + mesh.name + ": displaced UV sphere, " +
                                std::to_string(shape.segments_u) + " x " + std::to_string(shape.segments_v) +
                                " segments (bench/displaced_sphere.h)";
    write_ply(stem + ".ply", triangles, comment);
    write_obj(stem + ".obj", triangles, comment);
    write_glb(stem + ".glb", triangles, comment);
    write_scene(bench_scene_file(directory, mesh), mesh);
    write_instanced_scene(bench_instanced_scene_file(directory, mesh), mesh);
}

}  // namespace wt::bench
