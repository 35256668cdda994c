#include "bench_scene.h"

#include <filesystem>
#include <limits>
#include <string>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "bench_data.h"
#include "core/scene_file/scene_loader.h"

namespace wt::bench {

namespace {

constexpr char kHexroom[] = "hexroom";
constexpr char kScenePrefix[] = "hexroom_";

// The real model. assimp-testmodels has one mesh of more than 4k triangles in a format our
// loader reads (PLY, OBJ, glTF): this engine. Its Wuson.ply is 3,732; pond.0.ply is points.
constexpr char kModelName[] = "2cylinderengine";
constexpr char kModelFile[] = "/usr/share/assimp/models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb";

// The benchmarks' own settings. Shadow rays stay at the seed report's M = 3, which the
// scene files used until the default became 1, so bench/README.md's history keeps comparing
// like with like.
SceneDescription with_benchmark_settings(SceneDescription description, int width, int height, int spp) {
    description.settings.width = width;
    description.settings.height = height;
    description.settings.spp = spp;
    description.settings.shadow_rays = 3;
    return description;
}

// Appends `meshes` (whose material indices refer to `materials`) to `scene`, materials too.
void append_meshes(SceneDescription& scene, const std::vector<Material>& materials, std::vector<TriangleMesh> meshes) {
    const uint32_t first_material = uint32_t(scene.materials.size());
    scene.materials.insert(scene.materials.end(), materials.begin(), materials.end());
    for (TriangleMesh& mesh : meshes) {
        mesh.material += first_material;
        scene.meshes.push_back(std::move(mesh));
    }
}

// The model through the scene loader's mesh_file shape, fitted into the benchmark sphere's ball.
SceneDescription hexroom_with_model_description(const Ball& ball, int width, int height, int spp) {
    if (!std::filesystem::exists(kModelFile))
        throw SceneUnavailable(std::string(kModelFile) + " is missing: install Debian's assimp-testmodels (bench/install-bench-deps.sh)");
    const std::string model_scene = std::string(R"({"camera": {"eye": [-1, 0, 0], "look_at": [0, 0, 0]},
        "materials": {")") + kModelName + R"(": {"type": "lambertian", "albedo": [0.8, 0.8, 0.8]}},
        "shapes": [{"type": "mesh_file", "file": ")" + kModelFile + R"(", "material": ")" + kModelName + R"("}]})";
    SceneDescription model;
    try {
        model = parse_scene_json(model_scene, std::string("bench_scene.cpp's scene for ") + kModelName);
    } catch (const SceneError& e) {
        throw SceneUnavailable(std::string("the scene loader cannot load ") + kModelFile + ": " + e.what());
    }
    fit_into_ball(model.meshes, ball);
    SceneDescription scene = hexroom_description(width, height, spp);
    append_meshes(scene, model.materials, std::move(model.meshes));
    return scene;
}

}  // namespace

SceneDescription hexroom_description(int width, int height, int spp) {
    // WT_SCENES_DIR is the source tree's scenes/ (bench/CMakeLists.txt), so the programs run
    // from any working directory.
    return with_benchmark_settings(load_scene_file(std::string(WT_SCENES_DIR) + "/hexroom.json"), width, height, spp);
}

void fit_into_ball(std::vector<TriangleMesh>& meshes, const Ball& ball) {
    glm::vec3 lo(std::numeric_limits<float>::infinity()), hi(-std::numeric_limits<float>::infinity());
    for (const TriangleMesh& mesh : meshes)
        for (const glm::vec3& v : mesh.vertices) lo = glm::min(lo, v), hi = glm::max(hi, v);
    const glm::vec3 centre = 0.5f * (lo + hi);
    const float scale = ball.radius / (0.5f * glm::length(hi - lo));
    for (TriangleMesh& mesh : meshes)
        for (glm::vec3& v : mesh.vertices) v = ball.centre + scale * (v - centre);
}

Material added_mesh_material(const std::string& name) {
    Material material;
    material.name = name;
    material.type = MaterialType::lambertian;
    material.albedo = glm::vec3(0.8f);
    return material;
}

SceneDescription hexroom_with_sphere_description(const std::string& data_directory, const BenchmarkMesh& mesh, int width,
                                                 int height, int spp) {
    const std::string path = bench_scene_file(data_directory, mesh);
    if (!std::filesystem::exists(path))
        throw SceneUnavailable(path + " is missing: write it with `cmake --build build --target bench_data`");
    try {
        return with_benchmark_settings(load_scene_file(path), width, height, spp);
    } catch (const SceneError& e) {
        throw SceneUnavailable(e.what());
    }
}

std::vector<std::string> bench_scene_names() {
    std::vector<std::string> names = {kHexroom};
    for (const BenchmarkMesh& mesh : kBenchmarkMeshes) names.push_back(kScenePrefix + std::string(mesh.name));
    names.push_back(kScenePrefix + std::string(kModelName));
    return names;
}

BenchScene bench_scene(const std::string& name, int width, int height) {
    constexpr int kSpp = 1;
    if (name == kHexroom) return {name, hexroom_description(width, height, kSpp), std::nullopt};
    const Ball ball{kBenchmarkSphereCentre, kBenchmarkSphereBoundingRadius};
    for (const BenchmarkMesh& mesh : kBenchmarkMeshes)
        if (name == kScenePrefix + std::string(mesh.name))
            return {name, hexroom_with_sphere_description(WT_BENCH_DATA_DIR, mesh, width, height, kSpp), ball};
    if (name == kScenePrefix + std::string(kModelName)) return {name, hexroom_with_model_description(ball, width, height, kSpp), ball};
    throw std::invalid_argument("no benchmark scene named '" + name + "'");
}

}  // namespace wt::bench
