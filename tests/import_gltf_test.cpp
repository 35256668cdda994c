// glTF 2.0 through the scene loader: .gltf + .bin and .glb, node hierarchies whose transforms
// compose, several primitives, points and lines skipped, normals, materials, and bad buffers and
// accessors. Accessors (sparse, strided, data URIs) and primitive modes: import_gltf_*_test.cpp.

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <nlohmann/json.hpp>

#include "import_test_files.h"
#include "instance_scenes.h"

namespace {

using wt::MaterialType;
using wt::SceneDescription;
using wt::TriangleMesh;
using wt::test::Bytes;
using wt::test::expect_mesh_error;
using Json = nlohmann::json;
using Triangles = std::vector<std::array<uint32_t, 3>>;

using GltfImport = wt::test::ImportTest;

// The binary buffer: a triangle's positions (bytes 0-35) and normals (36-71), a square's
// positions (72-119) and its 6 unsigned-short indices (120-131).
std::string buffer_bytes() {
    Bytes b;
    for (float v : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f}) b.put(v);
    for (int k = 0; k < 3; ++k) b.put(1.f).put(0.f).put(0.f);
    for (float v : {0.f, 0.f, 1.f, 1.f, 0.f, 1.f, 1.f, 1.f, 1.f, 0.f, 1.f, 1.f}) b.put(v);
    for (uint16_t i : {0, 1, 2, 0, 2, 3}) b.put(i);
    return b.str();
}

// Node 0 translates by (10, 0, 0); its child node 1 rotates 90 degrees about z and scales by 2
// and holds mesh 0; node 1's child node 2 is a matrix translating by (0, 0, 5), holding mesh 0
// again. Mesh 0: the triangle (with normals, material 0), the square (indexed, material 1), and
// the triangle again as LINES (mode 1), to be skipped.
Json model(const std::string& buffer_uri) {
    const double s = std::sqrt(0.5);
    Json buffer = {{"byteLength", 132}};
    if (!buffer_uri.empty()) buffer["uri"] = buffer_uri;
    return {
        {"asset", {{"version", "2.0"}}},
        {"scene", 0},
        {"scenes", {{{"nodes", {0}}}}},
        {"nodes",
         {{{"translation", {10, 0, 0}}, {"children", {1}}},
          {{"rotation", {0, 0, s, s}}, {"scale", {2, 2, 2}}, {"mesh", 0}, {"children", {2}}},
          {{"matrix", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 5, 1}}, {"mesh", 0}}}},
        {"meshes",
         {{{"primitives",
            {{{"attributes", {{"POSITION", 0}, {"NORMAL", 1}}}, {"material", 0}},
             {{"attributes", {{"POSITION", 2}}}, {"indices", 3}, {"material", 1}},
             {{"attributes", {{"POSITION", 0}}}, {"mode", 1}}}}}}},
        {"materials",
         {{{"name", "red"}, {"pbrMetallicRoughness", {{"baseColorFactor", {0.8, 0.1, 0.1, 1}}, {"metallicFactor", 0}}}},
          {{"name", "lamp"}, {"emissiveFactor", {1, 2, 3}}, {"pbrMetallicRoughness", {{"metallicFactor", 0}}}}}},
        {"buffers", {buffer}},
        {"bufferViews",
         {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", 36}},
          {{"buffer", 0}, {"byteOffset", 36}, {"byteLength", 36}},
          {{"buffer", 0}, {"byteOffset", 72}, {"byteLength", 48}},
          {{"buffer", 0}, {"byteOffset", 120}, {"byteLength", 12}}}},
        {"accessors",
         {{{"bufferView", 0}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"}},
          {{"bufferView", 1}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"}},
          {{"bufferView", 2}, {"componentType", 5126}, {"count", 4}, {"type", "VEC3"}},
          {{"bufferView", 3}, {"componentType", 5123}, {"count", 6}, {"type", "SCALAR"}}}}};
}

void expect_vec3_near(const glm::vec3& actual, const glm::vec3& expected) {
    EXPECT_NEAR(actual.x, expected.x, 1e-5f);
    EXPECT_NEAR(actual.y, expected.y, 1e-5f);
    EXPECT_NEAR(actual.z, expected.z, 1e-5f);
}

// Mesh 0 is placed by two nodes: stored once in its own space, placed by two instances.
void expect_the_model(const SceneDescription& scene) {
    ASSERT_EQ(scene.meshes.size(), 0u);
    ASSERT_EQ(scene.prototypes.size(), 1u);
    ASSERT_EQ(scene.prototypes[0].parts.size(), 1u);
    ASSERT_EQ(scene.instances.size(), 2u);
    const TriangleMesh& mesh = scene.prototypes[0].parts[0];
    // The triangle's 3 vertices and the square's 4; the lines add none.
    ASSERT_EQ(mesh.vertices.size(), 7u);
    EXPECT_EQ(mesh.triangles, (Triangles{{0, 1, 2}, {3, 4, 5}, {3, 5, 6}}));
    const SceneDescription placed = wt::test::flattened(scene);
    ASSERT_EQ(placed.meshes.size(), 2u);
    const std::vector<glm::vec3>& first = placed.meshes[0].vertices;
    const std::vector<glm::vec3>& second = placed.meshes[1].vertices;
    // Node 1: x -> T(10,0,0) Rz(90) S(2) x. (1,0,0) -> (2,0,0) -> (0,2,0) -> (10,2,0).
    expect_vec3_near(first[0], {10, 0, 0});
    expect_vec3_near(first[1], {10, 2, 0});
    expect_vec3_near(first[2], {8, 0, 0});
    expect_vec3_near(first[5], {8, 2, 2});  // the square's (1, 1, 1)
    // Node 2 adds its own (0, 0, 5) first: (1,0,0) -> (1,0,5) -> (2,0,10) -> (0,2,10) -> (10,2,10).
    expect_vec3_near(second[0], {10, 0, 10});
    expect_vec3_near(second[1], {10, 2, 10});
    expect_vec3_near(second[5], {8, 2, 12});
    // The square has no NORMAL, so the mesh has no file normals.
    EXPECT_TRUE(mesh.normals.empty());
    ASSERT_EQ(scene.notes.size(), 2u);  // the LINES primitive (once, though placed twice), the normals
    EXPECT_NE(scene.notes[0].find("skipped mesh 0 primitive 2: mode 1, LINES: points and lines have no surface"),
              std::string::npos)
        << scene.notes[0];
    EXPECT_NE(scene.notes[1].find("some primitives have no NORMAL"), std::string::npos) << scene.notes[1];
}

TEST_F(GltfImport, GltfWithBinHierarchyAndPrimitives) {
    write("m.bin", buffer_bytes());
    write("m.gltf", model("m.bin").dump());
    expect_the_model(load_file("m.gltf"));
}

TEST_F(GltfImport, GlbIsTheSame) {
    write("m.glb", wt::test::glb(model("").dump(), buffer_bytes()));
    expect_the_model(load_file("m.glb"));
}

// A shared mesh with an emissive material (the file's "lamp") cannot be instanced (the light
// table lists the scene's own triangles): it is placed flattened, once per node, as before.
TEST_F(GltfImport, SharedEmissiveMeshIsFlattened) {
    write("m.bin", buffer_bytes());
    write("m.gltf", model("m.bin").dump());
    const SceneDescription scene = load(R"({"type": "mesh_file", "file": "m.gltf", "material": "from_file"})");
    EXPECT_TRUE(scene.instances.empty());
    ASSERT_EQ(scene.meshes.size(), 4u);  // (red triangle, lamp square) per node
    expect_vec3_near(scene.meshes[0].vertices[1], {10, 2, 0});
    expect_vec3_near(scene.meshes[2].vertices[1], {10, 2, 10});
    EXPECT_TRUE(scene.materials[scene.meshes[1].material].is_emissive());
}

TEST_F(GltfImport, NormalsFollowTheNodeRotation) {
    Json m = model("m.bin");
    m["meshes"][0]["primitives"] = Json::array({m["meshes"][0]["primitives"][0]});
    m["nodes"][1].erase("children");
    write("m.bin", buffer_bytes());
    write("m.gltf", m.dump());
    const TriangleMesh mesh = load_file("m.gltf").meshes[0];
    ASSERT_EQ(mesh.normals.size(), 3u);
    for (const glm::vec3& n : mesh.normals) expect_vec3_near(n, {0, 1, 0});  // (1,0,0) turned 90 degrees about z
}

TEST_F(GltfImport, OnlyAMirroringNodeHasItsWindingReversed) {
    Json m = model("m.bin");
    // Mesh 1 a copy of mesh 0, so each node places its own mesh once (flattened, not instanced).
    m["meshes"].push_back(m["meshes"][0]);
    m["nodes"] = Json::array({{{"children", {1, 2}}}, {{"scale", {-1, 1, 1}}, {"mesh", 0}}, {{"mesh", 1}}});
    write("m.bin", buffer_bytes());
    write("m.gltf", m.dump());
    const TriangleMesh mesh = load_file("m.gltf").meshes[0];
    EXPECT_EQ(mesh.triangles, (Triangles{{0, 2, 1}, {3, 5, 4}, {3, 6, 5}, {7, 8, 9}, {10, 11, 12}, {10, 12, 13}}));
    expect_vec3_near(mesh.vertices[1], {-1, 0, 0});
    expect_vec3_near(mesh.vertices[8], {1, 0, 0});
}

// Shared, the mesh keeps the file's winding once and the mirroring is the instance's (whose
// normals keep their side: instance_intersect_test.cpp).
TEST_F(GltfImport, SharedMeshMirroredByOneNode) {
    Json m = model("m.bin");
    m["nodes"] = Json::array({{{"children", {1, 2}}}, {{"scale", {-1, 1, 1}}, {"mesh", 0}}, {{"mesh", 0}}});
    write("m.bin", buffer_bytes());
    write("m.gltf", m.dump());
    const SceneDescription scene = load_file("m.gltf");
    ASSERT_EQ(scene.prototypes.size(), 1u);
    EXPECT_EQ(scene.prototypes[0].parts[0].triangles, (Triangles{{0, 1, 2}, {3, 4, 5}, {3, 5, 6}}));
    ASSERT_EQ(scene.instances.size(), 2u);
    EXPECT_LT(glm::determinant(glm::dmat3(scene.instances[0].transform)), 0.0);
    EXPECT_GT(glm::determinant(glm::dmat3(scene.instances[1].transform)), 0.0);
}

TEST_F(GltfImport, MaterialsFromFile) {
    Json m = model("m.bin");
    m["materials"].push_back({{"name", "glass"},
                              {"extensions",
                               {{"KHR_materials_transmission", {{"transmissionFactor", 1}}},
                                {"KHR_materials_ior", {{"ior", 1.4}}}}}});
    m["materials"].push_back({{"name", "chrome"},
                              {"pbrMetallicRoughness",
                               {{"baseColorFactor", {0.9, 0.9, 0.9, 1}}, {"metallicFactor", 1}, {"roughnessFactor", 0}}}});
    m["materials"][0]["occlusionTexture"] = {{"index", 0}};  // not rendered: a note
    m["meshes"][0]["primitives"][2]["material"] = 2;
    m["meshes"][0]["primitives"][2]["mode"] = 4;  // now drawn: the glass triangle
    m["meshes"][0]["primitives"].push_back({{"attributes", {{"POSITION", 2}}}, {"indices", 3}, {"material", 3}});
    m["nodes"][1].erase("children");
    write("m.bin", buffer_bytes());
    write("m.gltf", m.dump());
    const SceneDescription scene = load(R"({"type": "mesh_file", "file": "m.gltf", "material": "from_file"})");
    ASSERT_EQ(scene.materials.size(), 6u);
    EXPECT_EQ(scene.materials[2].name, "m.gltf/red");
    // glTF's roughnessFactor defaults to 1: a rough red plastic.
    EXPECT_EQ(scene.materials[2].type, MaterialType::principled);
    expect_vec3_near(scene.materials[2].base_color, {0.8f, 0.1f, 0.1f});
    EXPECT_EQ(scene.materials[2].metallic, 0.0f);
    EXPECT_EQ(scene.materials[2].roughness, 1.0f);
    EXPECT_EQ(scene.materials[3].name, "m.gltf/lamp");
    EXPECT_EQ(scene.materials[3].type, MaterialType::principled);
    EXPECT_EQ(scene.materials[3].emission, glm::vec3(1, 2, 3));
    // Transmission with glTF's default roughnessFactor, 1: frosted glass.
    EXPECT_EQ(scene.materials[4].type, MaterialType::rough_glass);
    EXPECT_FLOAT_EQ(scene.materials[4].roughness, 1.0f);
    EXPECT_FLOAT_EQ(scene.materials[4].ior, 1.4f);
    // Metallic 1, roughness 0: the smooth conductor of F0 baseColorFactor.
    EXPECT_EQ(scene.materials[5].type, MaterialType::conductor);
    expect_vec3_near(scene.materials[5].f0, glm::vec3(0.9f));
    ASSERT_EQ(scene.meshes.size(), 4u);
    EXPECT_EQ(scene.meshes[0].material, 2u);
    EXPECT_EQ(scene.meshes[1].material, 3u);
    EXPECT_EQ(scene.meshes[2].material, 4u);
    EXPECT_EQ(scene.meshes[3].material, 5u);
    ASSERT_EQ(scene.notes.size(), 2u);  // the normals (the squares have none), then the materials
    EXPECT_NE(scene.notes[1].find("not mapped from its materials: red: occlusionTexture"), std::string::npos)
        << scene.notes[1];
}

// ---------------------------------------------------------------------------------------------
// Bad input

TEST_F(GltfImport, GlbBufferTooShort) {
    write("m.glb", wt::test::glb(model("").dump(), buffer_bytes().substr(0, 100)));
    expect_mesh_error(error_for("m.glb"), "m.glb", "`byteLength' = 132, binary size = 100");  // tinygltf's words
}

TEST_F(GltfImport, BinFileTooShort) {
    write("m.bin", buffer_bytes().substr(0, 100));
    write("m.gltf", model("m.bin").dump());
    expect_mesh_error(error_for("m.gltf"), "m.gltf", "File size mismatch");
}

TEST_F(GltfImport, AccessorBeyondItsBufferView) {
    Json m = model("m.bin");
    m["accessors"][2]["count"] = 5;
    write("m.bin", buffer_bytes());
    write("m.gltf", m.dump());
    expect_mesh_error(error_for("m.gltf"), "m.gltf",
                      "accessor 2 (POSITION of mesh 0 primitive 1): 5 elements need 60 bytes of bufferView 2, which has 48");
}

TEST_F(GltfImport, BufferViewBeyondItsBuffer) {
    Json m = model("");
    m["bufferViews"][3]["byteOffset"] = 124;
    write("m.glb", wt::test::glb(m.dump(), buffer_bytes()));
    expect_mesh_error(error_for("m.glb"), "m.glb",
                      "bufferView 3 ends at byte 136 of buffer 0, which has only 132 bytes (the buffer is too short)");
}

TEST_F(GltfImport, IndexOutOfRange) {
    std::string bytes = buffer_bytes();
    bytes[130] = 9;  // the last index: 3 -> 9
    write("m.glb", wt::test::glb(model("").dump(), bytes));
    expect_mesh_error(error_for("m.glb"), "m.glb", "accessor 3 (indices of mesh 0 primitive 1): index 5 is 9, out of range (4 vertices)");
}

TEST_F(GltfImport, NanPosition) {
    std::string bytes = buffer_bytes();
    const float nan = std::numeric_limits<float>::quiet_NaN();
    std::memcpy(&bytes[16], &nan, 4);  // vertex 1's y
    write("m.glb", wt::test::glb(model("").dump(), bytes));
    expect_mesh_error(error_for("m.glb"), "m.glb", "accessor 0 (POSITION of mesh 0 primitive 0): element 1 is not finite");
}

TEST_F(GltfImport, MalformedJson) {
    write("m.gltf", "{\"asset\": {\"version\": \"2.0\"},");
    expect_mesh_error(error_for("m.gltf"), "m.gltf", "m.gltf: ");
}

TEST_F(GltfImport, ExponentialInstancingStops) {
    Json m = model("");
    Json nodes = Json::array();
    for (int i = 0; i < 40; ++i) nodes.push_back({{"children", {i + 1, i + 1}}});
    nodes.push_back(Json::object());  // no mesh: the test is the walk, not the copies
    m["nodes"] = nodes;
    write("m.glb", wt::test::glb(m.dump(), buffer_bytes()));
    expect_mesh_error(error_for("m.glb"), "m.glb", "the node hierarchy places more than 2^20 node instances");
}

TEST_F(GltfImport, EveryTruncatedGlbIsAnError) {
    const std::string whole = wt::test::glb(model("").dump(), buffer_bytes());
    for (std::size_t n = 0; n < whole.size(); ++n) {
        write("m.glb", whole.substr(0, n));
        EXPECT_NE(error_for("m.glb").find("m.glb"), std::string::npos) << n << " bytes";
    }
}

TEST_F(GltfImport, NoPrimitivesIsAnEmptyMesh) {
    Json m = model("");
    m["meshes"][0]["primitives"] = Json::array();
    write("m.glb", wt::test::glb(m.dump(), buffer_bytes()));
    expect_mesh_error(error_for("m.glb"), "m.glb", "the file has no triangles (an empty mesh)");
}

}  // namespace
