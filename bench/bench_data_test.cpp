// The benchmark meshes and their files: the displaced sphere is the closed, outward-wound,
// non-degenerate mesh the benchmarks assume, its normals are the surface's, the three file
// writers hold the same numbers, and the incoherent rays of a mesh scene never start inside it.

#include <gtest/gtest.h>

#include <unistd.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include "bench_data.h"
#include "bench_scene.h"
#include "core/scene_file/scene_loader.h"
#include "core/geometry/geometry_soa.h"
#include "core/scene/scene.h"
#include "displaced_sphere.h"
#include "kernels/accel/bvh.h"
#include "kernels/isa/intersect_dispatch.h"
#include "mesh_writers.h"
#include "workloads.h"

namespace wt::bench {
namespace {

namespace fs = std::filesystem;

glm::vec3 face_normal(const TriangleMesh& mesh, const std::array<uint32_t, 3>& t) {
    return glm::cross(mesh.vertices[t[1]] - mesh.vertices[t[0]], mesh.vertices[t[2]] - mesh.vertices[t[0]]);
}

TEST(DisplacedSphere, HasTheTriangleCountsTheBenchmarksAreNamedFor) {
    const std::size_t expected[] = {9'800, 99'224, 996'000};
    for (std::size_t k = 0; k < std::size(kBenchmarkMeshes); ++k) {
        const DisplacedSphereShape shape = benchmark_sphere(kBenchmarkMeshes[k].segments_u, kBenchmarkMeshes[k].segments_v);
        EXPECT_EQ(displaced_sphere_triangle_count(shape), expected[k]) << kBenchmarkMeshes[k].name;
    }
    const TriangleMesh mesh = displaced_sphere(benchmark_sphere(100, 50), 3);
    EXPECT_EQ(mesh.triangles.size(), 9'800u);
    EXPECT_EQ(mesh.vertices.size(), displaced_sphere_vertex_count(benchmark_sphere(100, 50)));
    EXPECT_EQ(mesh.normals.size(), mesh.vertices.size());
    EXPECT_EQ(mesh.material, 3u);
}

// Every edge is used once in each direction: closed, and every triangle wound the same way.
TEST(DisplacedSphere, IsClosedAndConsistentlyWound) {
    const TriangleMesh mesh = displaced_sphere(benchmark_sphere(316, 158), 0);
    std::map<std::pair<uint32_t, uint32_t>, int> directed_edges;
    for (const auto& t : mesh.triangles)
        for (int k = 0; k < 3; ++k) ++directed_edges[{t[k], t[(k + 1) % 3]}];
    for (const auto& [edge, count] : directed_edges) {
        ASSERT_EQ(count, 1) << edge.first << "->" << edge.second;
        ASSERT_EQ(directed_edges.count({edge.second, edge.first}), 1u) << "edge " << edge.first << "-" << edge.second << " is a boundary";
    }
}

TEST(DisplacedSphere, NoTriangleIsDegenerateAndAllFaceOutwards) {
    for (const BenchmarkMesh& size : kBenchmarkMeshes) {
        const DisplacedSphereShape shape = benchmark_sphere(size.segments_u, size.segments_v);
        const TriangleMesh mesh = displaced_sphere(shape, 0);
        std::size_t slivers = 0, inward = 0;
        for (const auto& t : mesh.triangles) {
            const glm::vec3 a = mesh.vertices[t[0]], b = mesh.vertices[t[1]], c = mesh.vertices[t[2]];
            slivers += is_sliver(a, b, c);
            inward += !(glm::dot(face_normal(mesh, t), (a + b + c) / 3.0f - shape.centre) > 0.0f);
        }
        EXPECT_EQ(slivers, 0u) << size.name;
        EXPECT_EQ(inward, 0u) << size.name;
    }
}

// The radius stays within +-amplitude of the sphere's and uses most of that range.
TEST(DisplacedSphere, DisplacementStaysWithinTheAmplitude) {
    const DisplacedSphereShape shape = benchmark_sphere(316, 158);
    const TriangleMesh mesh = displaced_sphere(shape, 0);
    float lowest = shape.radius, highest = shape.radius;
    for (const glm::vec3& v : mesh.vertices) {
        const float r = glm::length(v - shape.centre);
        lowest = std::fmin(lowest, r), highest = std::fmax(highest, r);
    }
    const float slack = 1e-5f;  // float rounding of the vertices
    EXPECT_GE(lowest, shape.radius - shape.amplitude - slack);
    EXPECT_LE(highest, kBenchmarkSphereBoundingRadius + slack);
    EXPECT_LT(lowest, shape.radius - 0.6f * shape.amplitude);
    EXPECT_GT(highest, shape.radius + 0.6f * shape.amplitude);
}

// The analytic normals are unit length and agree with the normals of the faces around each
// vertex (area-weighted average), which converge to the surface's as the mesh gets finer.
TEST(DisplacedSphere, NormalsAreTheSurfaceNormals) {
    const TriangleMesh mesh = displaced_sphere(benchmark_sphere(316, 158), 0);
    std::vector<glm::vec3> averaged(mesh.vertices.size(), glm::vec3(0.0f));
    for (const auto& t : mesh.triangles)
        for (uint32_t index : t) averaged[index] += face_normal(mesh, t);
    float worst_cosine = 1.0f;
    for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
        ASSERT_NEAR(glm::length(mesh.normals[i]), 1.0f, 1e-6f) << "vertex " << i;
        worst_cosine = std::fmin(worst_cosine, glm::dot(mesh.normals[i], glm::normalize(averaged[i])));
    }
    EXPECT_GT(worst_cosine, 0.999f);
    // And they are not simply the sphere's radial directions: the displacement tilts them.
    float least_radial = 1.0f;
    for (std::size_t i = 0; i < mesh.vertices.size(); ++i)
        least_radial = std::fmin(least_radial, glm::dot(mesh.normals[i], glm::normalize(mesh.vertices[i] - kBenchmarkSphereCentre)));
    EXPECT_LT(least_radial, 0.95f);
}

TEST(DisplacedSphere, IsDeterministic) {
    const TriangleMesh a = displaced_sphere(benchmark_sphere(100, 50), 0);
    const TriangleMesh b = displaced_sphere(benchmark_sphere(100, 50), 0);
    ASSERT_EQ(a.vertices.size(), b.vertices.size());
    EXPECT_EQ(std::memcmp(a.vertices.data(), b.vertices.data(), a.vertices.size() * sizeof(glm::vec3)), 0);
    EXPECT_EQ(std::memcmp(a.normals.data(), b.normals.data(), a.normals.size() * sizeof(glm::vec3)), 0);
    EXPECT_EQ(a.triangles, b.triangles);
}

TEST(DisplacedSphere, RejectsShapesItCannotBuild) {
    DisplacedSphereShape shape = benchmark_sphere(2, 50);
    EXPECT_THROW(displaced_sphere(shape, 0), std::invalid_argument);
    shape = benchmark_sphere(100, 1);
    EXPECT_THROW(displaced_sphere(shape, 0), std::invalid_argument);
    shape = benchmark_sphere(100, 50);
    shape.amplitude = shape.radius;
    EXPECT_THROW(displaced_sphere(shape, 0), std::invalid_argument);
}

// --- The files: read back by minimal readers of exactly what the writers write ---

std::string read_file(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream bytes;
    bytes << in.rdbuf();
    return bytes.str();
}

uint32_t le32(const std::string& bytes, std::size_t at) {
    uint32_t value = 0;
    for (int k = 3; k >= 0; --k) value = (value << 8) | uint8_t(bytes.at(at + std::size_t(k)));
    return value;
}

float lef32(const std::string& bytes, std::size_t at) {
    const uint32_t bits = le32(bytes, at);
    float value;
    std::memcpy(&value, &bits, sizeof value);
    return value;
}

glm::vec3 levec3(const std::string& bytes, std::size_t at) { return {lef32(bytes, at), lef32(bytes, at + 4), lef32(bytes, at + 8)}; }

class MeshFiles : public ::testing::Test {
protected:
    void SetUp() override {
        directory_ = fs::temp_directory_path() / ("wavetrace_bench_data_test_" + std::to_string(::getpid()));
        fs::create_directories(directory_);
    }
    void TearDown() override { fs::remove_all(directory_); }
    fs::path directory_;
    const TriangleMesh mesh_ = displaced_sphere(benchmark_sphere(20, 10), 0);
};

// Vertices and triangles bit for bit; normals bit for bit too unless normal_tolerance is given
// (the importers renormalise normals, which may move them by an ulp).
void expect_same_mesh(const TriangleMesh& expected, const TriangleMesh& read, float normal_tolerance = 0.0f) {
    ASSERT_EQ(read.vertices.size(), expected.vertices.size());
    ASSERT_EQ(read.normals.size(), expected.normals.size());
    for (std::size_t i = 0; i < expected.vertices.size(); ++i) {
        ASSERT_EQ(read.vertices[i], expected.vertices[i]) << "vertex " << i;
        if (normal_tolerance == 0.0f)
            ASSERT_EQ(read.normals[i], expected.normals[i]) << "normal " << i;
        else
            ASSERT_LE(glm::length(read.normals[i] - expected.normals[i]), normal_tolerance) << "normal " << i;
    }
    EXPECT_EQ(read.triangles, expected.triangles);
}

TEST_F(MeshFiles, PlyHoldsTheMeshBitForBit) {
    const fs::path path = directory_ / "m.ply";
    write_ply(path.string(), mesh_, "test");
    const std::string bytes = read_file(path);
    const std::string end = "end_header\n";
    const std::size_t body = bytes.find(end) + end.size();
    const std::string header = bytes.substr(0, body);
    EXPECT_EQ(header.rfind("ply\nformat binary_little_endian 1.0\ncomment test\n", 0), 0u) << header;
    EXPECT_NE(header.find("element vertex " + std::to_string(mesh_.vertices.size()) + "\n"), std::string::npos);
    EXPECT_NE(header.find("element face " + std::to_string(mesh_.triangles.size()) + "\n"), std::string::npos);
    TriangleMesh read;
    std::size_t at = body;
    for (std::size_t i = 0; i < mesh_.vertices.size(); ++i, at += 24) {
        read.vertices.push_back(levec3(bytes, at));
        read.normals.push_back(levec3(bytes, at + 12));
    }
    for (std::size_t i = 0; i < mesh_.triangles.size(); ++i, at += 13) {
        ASSERT_EQ(bytes.at(at), 3);
        read.triangles.push_back({le32(bytes, at + 1), le32(bytes, at + 5), le32(bytes, at + 9)});
    }
    EXPECT_EQ(at, bytes.size());
    expect_same_mesh(mesh_, read);
}

TEST_F(MeshFiles, ObjHoldsTheMeshBitForBit) {
    const fs::path path = directory_ / "m.obj";
    write_obj(path.string(), mesh_, "test");
    std::istringstream lines(read_file(path));
    TriangleMesh read;
    std::string line;
    while (std::getline(lines, line)) {
        std::istringstream words(line);
        std::string keyword;
        words >> keyword;
        if (keyword == "v" || keyword == "vn") {
            std::string x, y, z;
            words >> x >> y >> z;
            const glm::vec3 v(std::strtof(x.c_str(), nullptr), std::strtof(y.c_str(), nullptr), std::strtof(z.c_str(), nullptr));
            (keyword == "v" ? read.vertices : read.normals).push_back(v);
        } else if (keyword == "f") {
            std::array<uint32_t, 3> triangle;
            for (uint32_t& index : triangle) {
                std::string corner;
                words >> corner;
                const std::size_t slashes = corner.find("//");
                ASSERT_NE(slashes, std::string::npos) << line;
                ASSERT_EQ(corner.substr(0, slashes), corner.substr(slashes + 2)) << line;
                index = uint32_t(std::stoul(corner.substr(0, slashes)) - 1);
            }
            read.triangles.push_back(triangle);
        } else {
            ASSERT_EQ(keyword, "#") << line;
        }
    }
    expect_same_mesh(mesh_, read);
}

TEST_F(MeshFiles, GlbHoldsTheMeshBitForBit) {
    const fs::path path = directory_ / "m.glb";
    write_glb(path.string(), mesh_, "test");
    const std::string bytes = read_file(path);
    ASSERT_EQ(le32(bytes, 0), 0x46546C67u);  // "glTF"
    EXPECT_EQ(le32(bytes, 4), 2u);
    EXPECT_EQ(le32(bytes, 8), bytes.size());
    const uint32_t json_length = le32(bytes, 12);
    EXPECT_EQ(le32(bytes, 16), 0x4E4F534Au);  // "JSON"
    EXPECT_EQ(json_length % 4, 0u);
    const nlohmann::json document = nlohmann::json::parse(bytes.substr(20, json_length));
    const std::size_t bin = 20 + json_length + 8;
    EXPECT_EQ(le32(bytes, bin - 4), 0x004E4942u);  // "BIN\0"
    EXPECT_EQ(le32(bytes, bin - 8) % 4, 0u);
    EXPECT_GE(le32(bytes, bin - 8), document["buffers"][0]["byteLength"].get<std::size_t>());

    const nlohmann::json& primitive = document["meshes"][0]["primitives"][0];
    EXPECT_EQ(primitive["mode"], 4);
    // The start of an accessor's data in the file.
    auto data_of = [&](int accessor) {
        const nlohmann::json& view = document["bufferViews"][document["accessors"][accessor]["bufferView"].get<int>()];
        return bin + view.value("byteOffset", std::size_t(0));
    };
    const int positions = primitive["attributes"]["POSITION"], normals = primitive["attributes"]["NORMAL"], indices = primitive["indices"];
    EXPECT_EQ(document["accessors"][positions]["count"], mesh_.vertices.size());
    EXPECT_EQ(document["accessors"][indices]["count"], 3 * mesh_.triangles.size());
    TriangleMesh read;
    for (std::size_t i = 0; i < mesh_.vertices.size(); ++i) {
        read.vertices.push_back(levec3(bytes, data_of(positions) + 12 * i));
        read.normals.push_back(levec3(bytes, data_of(normals) + 12 * i));
    }
    for (std::size_t i = 0; i < mesh_.triangles.size(); ++i) {
        const std::size_t at = data_of(indices) + 12 * i;
        read.triangles.push_back({le32(bytes, at), le32(bytes, at + 4), le32(bytes, at + 8)});
    }
    expect_same_mesh(mesh_, read);
    // POSITION's min and max are required by glTF and must bound the vertices.
    for (int axis = 0; axis < 3; ++axis) {
        float lo = mesh_.vertices[0][axis], hi = lo;
        for (const glm::vec3& v : mesh_.vertices) lo = std::fmin(lo, v[axis]), hi = std::fmax(hi, v[axis]);
        EXPECT_EQ(document["accessors"][positions]["min"][axis].get<float>(), lo);
        EXPECT_EQ(document["accessors"][positions]["max"][axis].get<float>(), hi);
    }
}

TEST_F(MeshFiles, AFailedWriteLeavesNoFile) {
    const fs::path path = directory_ / "missing_directory" / "m.ply";
    EXPECT_THROW(write_ply(path.string(), mesh_, "test"), std::runtime_error);
    EXPECT_FALSE(fs::exists(path));
    EXPECT_TRUE(fs::is_empty(directory_));
}

// --- The scenes, through the scene loader's importers ---

constexpr const BenchmarkMesh& kMesh10k = kBenchmarkMeshes[0];

// The hexroom plus the mesh, as the bench_data files must describe it: the same vertices and
// triangles as displaced_sphere(), in the same order.
void expect_hexroom_with_mesh10k(const SceneDescription& scene) {
    const SceneDescription hexroom = hexroom_description(8, 8, 1);
    ASSERT_EQ(scene.meshes.size(), hexroom.meshes.size() + 1);
    ASSERT_EQ(scene.materials.size(), hexroom.materials.size() + 1);
    const Material& material = scene.materials.back();
    EXPECT_EQ(material.name, "mesh10k");
    EXPECT_EQ(material.albedo, added_mesh_material("mesh10k").albedo);
    const TriangleMesh& mesh = scene.meshes.back();
    EXPECT_EQ(mesh.material, hexroom.materials.size());
    expect_same_mesh(displaced_sphere(benchmark_sphere(kMesh10k.segments_u, kMesh10k.segments_v), 0), mesh, 1e-6f);
}

TEST_F(MeshFiles, TheSceneFileLoadsToTheHexroomAndTheMeshBitForBit) {
    write_bench_data(directory_.string(), kMesh10k);
    expect_hexroom_with_mesh10k(hexroom_with_sphere_description(directory_.string(), kMesh10k, 8, 8, 1));
}

// The scene references the PLY; the OBJ and glb beside it must import to the same bits.
TEST_F(MeshFiles, ObjAndGlbImportToTheSameMeshAsPly) {
    write_bench_data(directory_.string(), kMesh10k);
    const std::string ply_scene = read_file(bench_scene_file(directory_.string(), kMesh10k));
    for (const std::string extension : {".obj", ".glb"}) {
        std::string scene = ply_scene;
        const std::size_t at = scene.find("mesh10k.ply");
        ASSERT_NE(at, std::string::npos);
        scene.replace(at, std::string("mesh10k.ply").size(), "mesh10k" + extension);
        const fs::path path = directory_ / ("hexroom_mesh10k" + extension + ".json");
        std::ofstream(path) << scene;
        SCOPED_TRACE(extension);
        expect_hexroom_with_mesh10k(load_scene_file(path.string()));
    }
}

// The instanced scene: the hexroom with the mesh stored once and placed kBenchmarkInstances
// times, each copy's ball (the mesh's, scaled) clear of the others', the room's spheres and
// walls, and the light.
TEST_F(MeshFiles, TheInstancedSceneFilePlacesTheMeshInTheRoomsAir) {
    write_bench_data(directory_.string(), kMesh10k);
    const Scene scene = build_scene(load_scene_file(bench_instanced_scene_file(directory_.string(), kMesh10k)));
    const SceneDescription hexroom = hexroom_description(8, 8, 1);
    ASSERT_EQ(scene.instances.instances.size(), std::size_t(kBenchmarkInstances));
    ASSERT_EQ(scene.instances.meshes.size(), 1u);
    const std::size_t triangles = displaced_sphere_triangle_count(benchmark_sphere(kMesh10k.segments_u, kMesh10k.segments_v));
    EXPECT_EQ(scene.instances.meshes[0].triangles.size(), triangles);
    EXPECT_EQ(scene.instances.triangle_count, uint64_t(kBenchmarkInstances) * triangles);
    const float radius = kBenchmarkInstanceScale * kBenchmarkSphereBoundingRadius;
    std::vector<glm::vec3> centres;
    for (const Instance& instance : scene.instances.instances) {
        const glm::vec3 c = instance.to_world.point(kBenchmarkSphereCentre);
        for (const glm::vec3& other : centres) EXPECT_GT(glm::distance(c, other), 2.0f * radius);
        for (const Sphere& sphere : hexroom.spheres) EXPECT_GT(glm::distance(c, sphere.center), radius + sphere.radius);
        EXPECT_LT(c.z + radius, 4.99f);   // below the light and the ceiling
        EXPECT_GT(c.z - radius, -5.0f);   // above the floor
        EXPECT_LT(std::abs(c.y) + radius, 6.0f);  // between the side walls
        centres.push_back(c);
    }
}

TEST_F(MeshFiles, AMissingSceneFileMakesTheSceneUnavailable) {
    try {
        hexroom_with_sphere_description(directory_.string(), kMesh10k, 8, 8, 1);
        FAIL() << "no SceneUnavailable";
    } catch (const SceneUnavailable& e) {
        EXPECT_NE(std::string(e.what()).find("bench_data"), std::string::npos) << e.what();
    }
}

TEST(BenchScenes, NamesAndBalls) {
    EXPECT_FALSE(bench_scene("hexroom", 8, 8).solid.has_value());
    EXPECT_THROW(bench_scene("no_such_scene", 8, 8), std::invalid_argument);
    EXPECT_EQ(bench_scene_names().size(), 5u);
}

TEST(BenchScenes, FittingIntoTheBallPutsTheBoxCornersOnIt) {
    std::vector<TriangleMesh> meshes(2);
    meshes[0].vertices = {{-10, 0, 0}, {0, 4, 1}};
    meshes[1].vertices = {{2, -4, 3}};  // the box is [-10, 2] x [-4, 4] x [0, 3]
    const Ball ball{{5, 0, 1.5f}, 2.2f};
    fit_into_ball(meshes, ball);
    glm::vec3 lo(1e30f), hi(-1e30f);
    for (const TriangleMesh& mesh : meshes)
        for (const glm::vec3& v : mesh.vertices) lo = glm::min(lo, v), hi = glm::max(hi, v);
    EXPECT_NEAR(glm::length(0.5f * (lo + hi) - ball.centre), 0.0f, 1e-5f);
    EXPECT_NEAR(0.5f * glm::length(hi - lo), ball.radius, 1e-5f);
    // Uniformly: the box keeps its proportions 12 : 8 : 3.
    EXPECT_NEAR((hi.x - lo.x) / (hi.y - lo.y), 1.5f, 1e-5f);
    EXPECT_NEAR((hi.z - lo.z) / (hi.y - lo.y), 0.375f, 1e-5f);
}

TEST(BenchScenes, IncoherentRaysNeverStartInsideTheMeshBall) {
    SceneDescription with_sphere = hexroom_description(8, 8, 1);
    with_sphere.meshes.push_back(displaced_sphere(benchmark_sphere(100, 50), 0));
    const BenchScene description{"test", with_sphere, Ball{kBenchmarkSphereCentre, kBenchmarkSphereBoundingRadius}};
    const Scene scene = build_scene(description.description);
    const RaySet rays = incoherent_rays(scene, description.solid, 0, 20'000, 1);
    for (std::size_t i = 0; i < rays.size(); ++i)
        ASSERT_GE(glm::length(rays.ray(i).origin - description.solid->centre), description.solid->radius) << "ray " << i;
    // Without the ball some of the same stream's origins are inside it: the exclusion is real.
    const RaySet unconstrained = incoherent_rays(scene, std::nullopt, 0, 20'000, 1);
    std::size_t inside = 0;
    for (std::size_t i = 0; i < unconstrained.size(); ++i)
        inside += glm::length(unconstrained.ray(i).origin - description.solid->centre) < description.solid->radius;
    EXPECT_GT(inside, 0u);
}

// The bounce workload: rays from the surfaces the incoherent rays hit, the mesh's and the room's,
// unit directions, the asked-for count, the same bits every time.
TEST(BenchScenes, BounceRaysStartOnTheMeshAndTheRoom) {
    SceneDescription with_sphere = hexroom_description(8, 8, 1);
    with_sphere.meshes.push_back(displaced_sphere(benchmark_sphere(100, 50), 0));
    const Ball ball{kBenchmarkSphereCentre, kBenchmarkSphereBoundingRadius};
    const Scene scene = build_scene(with_sphere);
    const Bvh bvh = build_bvh(scene);
    const ClosestHitFunction closest = [&](const RayView& rays, const HitView& hits) {
        intersect_kernels(Isa::scalar).closest_bvh(bvh_view(bvh), rays, hits);
    };
    const RaySet rays = bounce_rays(scene, ball, closest, 5'000, 1, 3);
    ASSERT_EQ(rays.size(), 5'000u);
    std::size_t on_mesh = 0;
    for (std::size_t i = 0; i < rays.size(); ++i) {
        const Ray ray = rays.ray(i);
        ASSERT_NEAR(glm::length(ray.direction), 1.0f, 1e-5f) << "ray " << i;
        on_mesh += glm::length(ray.origin - ball.centre) < ball.radius;
    }
    EXPECT_GT(on_mesh, 0u);
    EXPECT_LT(on_mesh, rays.size());
    const RaySet again = bounce_rays(scene, ball, closest, 5'000, 1, 3);
    EXPECT_EQ(std::memcmp(again.ox.data(), rays.ox.data(), rays.size() * sizeof(float)), 0);
    EXPECT_EQ(std::memcmp(again.dz.data(), rays.dz.data(), rays.size() * sizeof(float)), 0);
}

}  // namespace
}  // namespace wt::bench
