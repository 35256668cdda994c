// glTF primitive modes (glTF 2.0, 3.7.2.1): triangles, strips and fans become triangles that
// all face the way the file's winding says; points and lines are skipped, and alone they are
// an error that says so. Files of another glTF version, or requiring an extension that stores
// the geometry differently, are refused as such.

#include <cstring>

#include <glm/geometric.hpp>

#include "import_gltf_files.h"

namespace {

using wt::TriangleMesh;
using wt::test::expect_mesh_error;
using wt::test::GltfFile;
using Json = nlohmann::json;
using Triangles = std::vector<std::array<uint32_t, 3>>;
using Points = std::vector<std::array<float, 3>>;

using GltfPrimitives = wt::test::ImportTest;

// A zig-zag along x: bottom, top, bottom, top, ... (the usual strip of quads).
const Points kZigZag{{0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {1, 1, 0}, {2, 0, 0}, {2, 1, 0}};
// A fan around the origin: the centre, then points counter-clockwise seen from +z.
const Points kFan{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {-1, 1, 0}};

// Every triangle's geometric normal (unnormalised) has the sign `z` in z.
void expect_all_face(const TriangleMesh& mesh, float z) {
    for (const auto& t : mesh.triangles) {
        const glm::vec3 n = glm::cross(mesh.vertices[t[1]] - mesh.vertices[t[0]], mesh.vertices[t[2]] - mesh.vertices[t[0]]);
        EXPECT_GT(n.z * z, 0.0f) << t[0] << " " << t[1] << " " << t[2];
    }
}

TEST_F(GltfPrimitives, AStripAlternatesSoEveryTriangleFacesTheSameWay) {
    GltfFile f;
    f.primitive({{"attributes", {{"POSITION", f.positions(kZigZag)}}}, {"mode", 5}});
    write("m.gltf", f.gltf());
    const TriangleMesh mesh = load_file("m.gltf").meshes[0];
    // p_i = {v_i, v_i+(1+i%2), v_i+(2-i%2)}
    EXPECT_EQ(mesh.triangles, (Triangles{{0, 1, 2}, {1, 3, 2}, {2, 3, 4}, {3, 5, 4}}));
    expect_all_face(mesh, -1.0f);
}

TEST_F(GltfPrimitives, AnIndexedStripReadsItsIndicesInOrder) {
    // The vertices shuffled, the indices undoing it, as unsigned bytes (the asset generator's
    // Mesh_PrimitiveMode_11 is an indexed strip too).
    const Points shuffled{kZigZag[3], kZigZag[0], kZigZag[5], kZigZag[1], kZigZag[4], kZigZag[2]};
    GltfFile f;
    f.primitive({{"attributes", {{"POSITION", f.positions(shuffled)}}}, {"indices", f.indices({1, 3, 5, 0, 4, 2}, 5121)}, {"mode", 5}});
    write("m.gltf", f.gltf());
    const TriangleMesh mesh = load_file("m.gltf").meshes[0];
    EXPECT_EQ(mesh.triangles, (Triangles{{1, 3, 5}, {3, 0, 5}, {5, 0, 4}, {0, 2, 4}}));
    expect_all_face(mesh, -1.0f);
}

TEST_F(GltfPrimitives, AFanTurnsAroundItsFirstVertex) {
    GltfFile f;
    f.primitive({{"attributes", {{"POSITION", f.positions(kFan)}}}, {"mode", 6}});
    f.primitive({{"attributes", {{"POSITION", f.positions(kFan)}}}, {"indices", f.indices({0, 1, 2, 3, 4}, 5123)}, {"mode", 6}});
    write("m.gltf", f.gltf());
    const TriangleMesh mesh = load_file("m.gltf").meshes[0];
    // p_i = {v_i+1, v_i+2, v_0}, the second primitive's vertices after the first's five.
    EXPECT_EQ(mesh.triangles, (Triangles{{1, 2, 0}, {2, 3, 0}, {3, 4, 0}, {6, 7, 5}, {7, 8, 5}, {8, 9, 5}}));
    expect_all_face(mesh, 1.0f);
}

TEST_F(GltfPrimitives, AStripOrFanNeedsThreeVertices) {
    for (const int mode : {5, 6}) {
        GltfFile f;
        f.primitive({{"attributes", {{"POSITION", f.positions({{0, 0, 0}, {1, 0, 0}})}}}, {"mode", mode}});
        write("m.gltf", f.gltf());
        expect_mesh_error(error_for("m.gltf"), "m.gltf",
                          std::string("mesh 0 primitive 0: 2 vertices, fewer than the 3 a ") + (mode == 5 ? "strip" : "fan") + " needs");
        GltfFile g;
        g.primitive({{"attributes", {{"POSITION", g.positions(kFan)}}}, {"indices", g.indices({0, 1}, 5121)}, {"mode", mode}});
        write("m.gltf", g.gltf());
        expect_mesh_error(error_for("m.gltf"), "m.gltf", "accessor 1 (indices of mesh 0 primitive 0): 2 indices, fewer than the 3");
    }
}

TEST_F(GltfPrimitives, TrianglesNeedAMultipleOfThree) {
    GltfFile f;
    f.primitive({{"attributes", {{"POSITION", f.positions(kFan)}}}, {"indices", f.indices({0, 1, 2, 3}, 5121)}});
    write("m.gltf", f.gltf());
    expect_mesh_error(error_for("m.gltf"), "m.gltf", "accessor 1 (indices of mesh 0 primitive 0): 4 indices, not a multiple of 3");
}

TEST_F(GltfPrimitives, PointsAndLinesAloneAreAnErrorThatSaysSo) {
    for (const int mode : {0, 1, 2, 3}) {
        GltfFile f;
        f.primitive({{"attributes", {{"POSITION", f.positions(kFan)}}}, {"mode", mode}});
        write("m.gltf", f.gltf());
        static const char* const kNames[] = {"POINTS", "LINES", "LINE_LOOP", "LINE_STRIP"};
        expect_mesh_error(error_for("m.gltf"), "m.gltf",
                          "no triangles: its primitives are points or lines (mesh 0 primitive 0: mode " + std::to_string(mode) +
                              ", " + kNames[mode] + "), which have no surface to render");
    }
}

TEST_F(GltfPrimitives, AModeOutsideTheSpecificationIsAnError) {
    GltfFile f;
    f.primitive({{"attributes", {{"POSITION", f.positions(kFan)}}}, {"mode", 7}});
    write("m.gltf", f.gltf());
    expect_mesh_error(error_for("m.gltf"), "m.gltf", "mesh 0 primitive 0: mode 7 is not a glTF primitive mode (0 to 6)");
}

// ---------------------------------------------------------------------------------------------
// Versions and required extensions

TEST_F(GltfPrimitives, GltfOneIsRefusedAsSuch) {
    const std::string message = "glTF 1.0 is not supported (version 2.0 is)";
    // As collada2gltf wrote them: dictionaries where 2.0 has arrays, version "1.0" (which
    // tinygltf parses into a model with no meshes), 1 as a number (which it refuses), or none.
    const Json one = {{"asset", {{"version", "1.0"}}},
                      {"scene", "defaultScene"},
                      {"scenes", {{"defaultScene", {{"nodes", {"node_1"}}}}}},
                      {"nodes", {{"node_1", {{"meshes", {"mesh_1"}}}}}},
                      {"meshes", {{"mesh_1", {{"primitives", {{{"attributes", {{"POSITION", "accessor_1"}}}, {"mode", 4}}}}}}}}};
    write("string.gltf", one.dump());
    expect_mesh_error(error_for("string.gltf"), "string.gltf", message);
    Json number = one;
    number["asset"]["version"] = 1;
    write("number.gltf", number.dump());
    expect_mesh_error(error_for("number.gltf"), "number.gltf", message);
    Json none = one;
    none.erase("asset");
    write("none.gltf", none.dump());
    expect_mesh_error(error_for("none.gltf"), "none.gltf", message);
    // glTF 1.0's binary container (KHR_binary_glTF): version 1 in the header.
    std::string binary = wt::test::glb(one.dump(), "");
    binary[4] = 1;
    write("one.glb", binary);
    expect_mesh_error(error_for("one.glb"), "one.glb", message);
}

// A .glb whose BIN chunk claims more bytes than the file holds is refused naming the chunk, by
// the 8 bytes of its own header that tinygltf leaves out of its bound (it would read them past
// the mapped file) as by 4; the same file with the chunk's true length loads.
TEST_F(GltfPrimitives, AGlbBinChunkPastTheFileIsRefused) {
    GltfFile f;
    f.primitive({{"attributes", {{"POSITION", f.positions(kFan)}}}, {"mode", 6}});
    const std::string whole = f.glb_bytes();
    write("whole.glb", whole);
    EXPECT_EQ(load_file("whole.glb").meshes[0].triangles.size(), 3u);
    uint32_t json_length = 0, bin_length = 0;
    std::memcpy(&json_length, whole.data() + 12, 4);
    const std::size_t bin_chunk = 20 + json_length;
    std::memcpy(&bin_length, whole.data() + bin_chunk, 4);
    ASSERT_EQ(bin_chunk + 8 + bin_length, whole.size());
    for (uint32_t extra : {4u, 8u}) {
        std::string claims_more = whole;
        const uint32_t claimed = bin_length + extra;
        std::memcpy(&claims_more[bin_chunk], &claimed, 4);
        // The buffer asks for what the chunk claims, so only the chunk's bound stands in the way.
        Json j = Json::parse(claims_more.substr(20, json_length));
        j["buffers"][0]["byteLength"] = claimed;
        std::string json = j.dump();
        ASSERT_LE(json.size(), json_length) << "the JSON chunk keeps its length";
        json.resize(json_length, ' ');
        claims_more.replace(20, json_length, json);
        write("past.glb", claims_more);
        expect_mesh_error(error_for("past.glb"), "past.glb",
                          "the BIN chunk at byte " + std::to_string(bin_chunk) + " claims " + std::to_string(claimed) +
                              " bytes, which would end at byte " + std::to_string(bin_chunk + 8 + claimed) + ", past the " +
                              std::to_string(whole.size()) + " bytes of the file");
    }
}

TEST_F(GltfPrimitives, OtherVersionsAreRefusedAndTwoPointAnythingIsRead) {
    GltfFile f;
    f.primitive({{"attributes", {{"POSITION", f.positions(kFan)}}}, {"mode", 6}});
    Json m = Json::parse(f.gltf());
    m["asset"]["version"] = "3.0";
    write("three.gltf", m.dump());
    expect_mesh_error(error_for("three.gltf"), "three.gltf", "three.gltf: glTF 3.0 is not supported (version 2.0 is)");
    m["asset"]["version"] = "2.1";  // a later minor version of 2 is meant to load
    write("two.gltf", m.dump());
    EXPECT_EQ(load_file("two.gltf").meshes[0].triangles.size(), 3u);
}

TEST_F(GltfPrimitives, ARequiredGeometryExtensionIsRefused) {
    GltfFile f;
    f.primitive({{"attributes", {{"POSITION", f.positions(kFan)}}}, {"mode", 6}});
    Json m = Json::parse(f.gltf());
    for (const char* extension : {"KHR_draco_mesh_compression", "KHR_mesh_quantization", "EXT_meshopt_compression"}) {
        m["extensionsUsed"] = m["extensionsRequired"] = {extension};
        write("m.gltf", m.dump());
        expect_mesh_error(error_for("m.gltf"), "m.gltf",
                          "m.gltf: requires extension " + std::string(extension) + " (extensionsRequired), which is not supported");
    }
    // As Draco files are: the indices have no bufferView, which tinygltf refuses before we look.
    m["extensionsUsed"] = m["extensionsRequired"] = {"KHR_draco_mesh_compression"};
    m["accessors"].push_back({{"componentType", 5123}, {"count", 3}, {"type", "SCALAR"}});
    m["meshes"][0]["primitives"][0]["indices"] = 1;
    write("m.gltf", m.dump());
    expect_mesh_error(error_for("m.gltf"), "m.gltf", "requires extension KHR_draco_mesh_compression (extensionsRequired)");
    // Used but not required: the file is meant to load without it.
    m = Json::parse(f.gltf());
    m["extensionsUsed"] = {"KHR_draco_mesh_compression"};
    write("m.gltf", m.dump());
    EXPECT_EQ(load_file("m.gltf").meshes[0].triangles.size(), 3u);
}

}  // namespace
