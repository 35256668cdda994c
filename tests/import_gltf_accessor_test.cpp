// glTF accessors as the specification lays them out (glTF 2.0, 3.6.2): interleaved vertices
// (byteStride), index component types, buffers in data URIs, and sparse accessors over a
// bufferView or over zeros; and each way they can be wrong.

#include "import_gltf_files.h"

namespace {

using wt::SceneDescription;
using wt::TriangleMesh;
using wt::test::Bytes;
using wt::test::expect_mesh_error;
using wt::test::GltfFile;
using Json = nlohmann::json;
using Triangles = std::vector<std::array<uint32_t, 3>>;
using Points = std::vector<std::array<float, 3>>;

using GltfAccessors = wt::test::ImportTest;

const Points kSquare{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};

std::vector<glm::vec3> vec3s(const Points& points) {
    std::vector<glm::vec3> out;
    for (const auto& p : points) out.push_back({p[0], p[1], p[2]});
    return out;
}

// ---------------------------------------------------------------------------------------------
// Interleaved vertices, index types, data URIs

TEST_F(GltfAccessors, InterleavedPositionsAndNormalsFollowTheByteStride) {
    // One bufferView of 28-byte vertices: position, normal, then 4 bytes the accessors skip.
    const Points normals{{0, 0, 1}, {0, 0.6f, 0.8f}, {0, 0, 1}, {0.6f, 0, 0.8f}};
    Bytes b;
    for (std::size_t v = 0; v < 4; ++v) {
        for (float c : kSquare[v]) b.put(c);
        for (float c : normals[v]) b.put(c);
        b.put(uint32_t(0xFFFFFFFF));  // NaN as a float: read, it would fail the test loudly
    }
    GltfFile f;
    // The last vertex ends 4 bytes before the view does: the bound is the last element, not a stride.
    const int view = f.view(b.str().substr(0, 3 * 28 + 24), 28);
    const int positions = f.accessor({{"bufferView", view}, {"componentType", 5126}, {"count", 4}, {"type", "VEC3"}});
    const int normal = f.accessor({{"bufferView", view}, {"byteOffset", 12}, {"componentType", 5126}, {"count", 4}, {"type", "VEC3"}});
    f.primitive({{"attributes", {{"POSITION", positions}, {"NORMAL", normal}}}, {"indices", f.indices({0, 1, 2, 0, 2, 3}, 5125)}});
    write("m.gltf", f.gltf());
    const TriangleMesh mesh = load_file("m.gltf").meshes[0];
    EXPECT_EQ(mesh.vertices, vec3s(kSquare));
    ASSERT_EQ(mesh.normals.size(), 4u);
    for (std::size_t v = 0; v < 4; ++v) {
        EXPECT_NEAR(mesh.normals[v].x, normals[v][0], 1e-7f) << v;
        EXPECT_NEAR(mesh.normals[v].y, normals[v][1], 1e-7f) << v;
        EXPECT_NEAR(mesh.normals[v].z, normals[v][2], 1e-7f) << v;
    }
    EXPECT_EQ(mesh.triangles, (Triangles{{0, 1, 2}, {0, 2, 3}}));
}

TEST_F(GltfAccessors, EveryIndexComponentTypeGivesTheSameTriangles) {
    for (const int type : {5121, 5123, 5125}) {
        SCOPED_TRACE(type);
        GltfFile f;
        f.primitive({{"attributes", {{"POSITION", f.positions(kSquare)}}}, {"indices", f.indices({2, 1, 0, 3, 2, 0}, type)}});
        write("m.gltf", f.gltf());
        EXPECT_EQ(load_file("m.gltf").meshes[0].triangles, (Triangles{{2, 1, 0}, {3, 2, 0}}));
    }
}

TEST_F(GltfAccessors, AnIndexViewWithAByteStrideIsReadWithIt) {
    // Unusual (the specification defines byteStride for vertex attributes) but unambiguous.
    Bytes b;
    for (uint16_t i : {0, 1, 2}) b.put(i).put(uint16_t(9));
    GltfFile f;
    const int indices = f.accessor({{"bufferView", f.view(b.str(), 4)}, {"componentType", 5123}, {"count", 3}, {"type", "SCALAR"}});
    f.primitive({{"attributes", {{"POSITION", f.positions(kSquare)}}}, {"indices", indices}});
    write("m.gltf", f.gltf());
    EXPECT_EQ(load_file("m.gltf").meshes[0].triangles, (Triangles{{0, 1, 2}}));
}

TEST_F(GltfAccessors, ADataUriBufferIsTheSameAsABinFile) {
    GltfFile f;
    f.primitive({{"attributes", {{"POSITION", f.positions(kSquare)}}}, {"indices", f.indices({0, 1, 2, 0, 2, 3}, 5123)}});
    write("uri.gltf", f.gltf());
    write("m.bin", f.bin());
    write("bin.gltf", f.json("m.bin").dump());
    write("m.glb", f.glb_bytes());
    const TriangleMesh reference = load_file("bin.gltf").meshes[0];
    for (const char* file : {"uri.gltf", "m.glb"}) {
        SCOPED_TRACE(file);
        const TriangleMesh mesh = load_file(file).meshes[0];
        EXPECT_EQ(mesh.vertices, reference.vertices);
        EXPECT_EQ(mesh.triangles, reference.triangles);
    }
    EXPECT_EQ(reference.vertices, vec3s(kSquare));
}

TEST_F(GltfAccessors, BadDataUris) {
    GltfFile f;
    f.primitive({{"attributes", {{"POSITION", f.positions(kSquare)}}}});
    Json m = f.json("data:application/octet-stream;base64," + wt::test::base64(f.bin()));
    m["buffers"][0]["byteLength"] = 60;  // the decoded data has 48
    write("long.gltf", m.dump());
    // tinygltf's words, with the URI cut short: it could be megabytes.
    expect_mesh_error(error_for("long.gltf"), "long.gltf",
                      "long.gltf: Failed to decode 'uri' : data:application/octet-stream;base64,AAAAAAAAAAAAAAAA... (64 characters) "
                      "in Buffer");
    m["buffers"][0]["byteLength"] = 48;
    m["buffers"][0]["uri"] = "data:application/octet-stream;base64,AAAA*AAA";
    write("bad.gltf", m.dump());
    expect_mesh_error(error_for("bad.gltf"), "bad.gltf",
                      "bad.gltf: Failed to decode 'uri' : data:application/octet-stream;base64,AAAA*AAA in Buffer");
}

TEST_F(GltfAccessors, StridesShorterThanAnElementOrPastTheViewAreErrors) {
    const struct { int stride; std::size_t view_bytes; std::string problem; } cases[] = {
        {8, 48, "bufferView 0 has byteStride 8, less than one element (12 bytes)"},
        // The third vertex at bytes 48..60 of a 56-byte view.
        {24, 56, "3 elements need 60 bytes of bufferView 0, which has 56"},
    };
    for (const auto& c : cases) {
        SCOPED_TRACE(c.stride);
        GltfFile f;
        const int view = f.view(std::string(c.view_bytes, '\0'), c.stride);
        f.primitive({{"attributes", {{"POSITION", f.accessor({{"bufferView", view}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"}})}}}});
        write("m.gltf", f.gltf());
        expect_mesh_error(error_for("m.gltf"), "m.gltf", "accessor 0 (POSITION of mesh 0 primitive 0): " + c.problem);
    }
}

TEST_F(GltfAccessors, WrongTypesAndComponentTypesAreNamed) {
    GltfFile f;
    const int positions = f.positions(kSquare);
    const int shorts = f.indices({0, 1, 2}, 5123);
    f.primitive({{"attributes", {{"POSITION", shorts}}}});
    write("type.gltf", f.gltf());
    expect_mesh_error(error_for("type.gltf"), "type.gltf", "accessor 1 (POSITION of mesh 0 primitive 0): expected type VEC3, got SCALAR");
    GltfFile g;
    const int float_indices = g.accessor({{"bufferView", g.view(std::string(12, '\0'))}, {"componentType", 5126}, {"count", 3}, {"type", "SCALAR"}});
    g.primitive({{"attributes", {{"POSITION", g.positions(kSquare)}}}, {"indices", float_indices}});
    write("component.gltf", g.gltf());
    expect_mesh_error(error_for("component.gltf"), "component.gltf",
                      "accessor 0 (indices of mesh 0 primitive 0): componentType FLOAT (5126), expected UNSIGNED_BYTE (5121), "
                      "UNSIGNED_SHORT (5123) or UNSIGNED_INT (5125)");
    (void)positions;
}

// ---------------------------------------------------------------------------------------------
// Sparse accessors (3.6.2.3): count indices, strictly increasing, and as many values

// A sparse block replacing elements `at` by `values` (FLOAT VEC3), the indices of `index_type`.
Json sparse(GltfFile& f, const std::vector<uint32_t>& at, const Points& values, int index_type) {
    Bytes idx, val;
    for (uint32_t i : at) {
        if (index_type == 5121) idx.put(uint8_t(i));
        else if (index_type == 5123) idx.put(uint16_t(i));
        else idx.put(i);
    }
    for (const auto& v : values) val.put(v[0]).put(v[1]).put(v[2]);
    return {{"count", at.size()},
            {"indices", {{"bufferView", f.view(idx.str())}, {"componentType", index_type}}},
            {"values", {{"bufferView", f.view(val.str())}}}};
}

TEST_F(GltfAccessors, SparseValuesReplaceTheirElementsOfTheBufferView) {
    for (const int index_type : {5121, 5123, 5125}) {
        SCOPED_TRACE(index_type);
        GltfFile f;
        const int positions = f.positions(kSquare);
        f.accessor_json(positions)["sparse"] = sparse(f, {1, 3}, {{5, 0, 0}, {0, 5, 0}}, index_type);
        f.primitive({{"attributes", {{"POSITION", positions}}}, {"indices", f.indices({0, 1, 2, 0, 2, 3}, 5123)}});
        write("m.gltf", f.gltf());
        EXPECT_EQ(load_file("m.gltf").meshes[0].vertices, vec3s({{0, 0, 0}, {5, 0, 0}, {1, 1, 0}, {0, 5, 0}}));
    }
}

TEST_F(GltfAccessors, ASparseAccessorWithoutABufferViewIsZerosWithItsValues) {
    GltfFile f;
    const int positions = f.accessor({{"componentType", 5126}, {"count", 4}, {"type", "VEC3"}});
    f.accessor_json(positions)["sparse"] = sparse(f, {1, 2, 3}, {{1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, 5121);
    f.primitive({{"attributes", {{"POSITION", positions}}}, {"indices", f.indices({0, 1, 2, 0, 2, 3}, 5121)}});
    write("m.gltf", f.gltf());
    EXPECT_EQ(load_file("m.gltf").meshes[0].vertices, vec3s(kSquare));
}

TEST_F(GltfAccessors, SparseIndicesAreSubstitutedToo) {
    // The index accessor (0 1 2, 0 2 3) with its element 4 replaced: the second triangle is 0 1 3.
    GltfFile f;
    const int indices = f.indices({0, 1, 2, 0, 2, 3}, 5123);
    Bytes at, value;
    at.put(uint8_t(4));
    value.put(uint16_t(1));
    f.accessor_json(indices)["sparse"] = {{"count", 1},
                                          {"indices", {{"bufferView", f.view(at.str())}, {"componentType", 5121}}},
                                          {"values", {{"bufferView", f.view(value.str())}}}};
    f.primitive({{"attributes", {{"POSITION", f.positions(kSquare)}}}, {"indices", indices}});
    write("m.gltf", f.gltf());
    EXPECT_EQ(load_file("m.gltf").meshes[0].triangles, (Triangles{{0, 1, 2}, {0, 1, 3}}));
}

TEST_F(GltfAccessors, SparseValuesAreCheckedLikeTheOthers) {
    GltfFile f;
    const int positions = f.positions(kSquare);
    f.accessor_json(positions)["sparse"] = sparse(f, {1}, {{std::nanf(""), 0, 0}}, 5121);
    f.primitive({{"attributes", {{"POSITION", positions}}}, {"indices", f.indices({0, 1, 2}, 5121)}});
    write("m.gltf", f.gltf());
    expect_mesh_error(error_for("m.gltf"), "m.gltf", "accessor 0 (POSITION of mesh 0 primitive 0): element 1 is not finite");
}

TEST_F(GltfAccessors, BadSparseAccessorsNameWhatIsWrong) {
    const std::string accessor = "accessor 0 (POSITION of mesh 0 primitive 0): ";
    const struct {
        const char* name;
        std::vector<uint32_t> at;
        int index_type;
        void (*change)(Json& sparse, Json& views);
        std::string problem;
    } cases[] = {
        {"decreasing", {2, 1}, 5121, nullptr, "sparse.indices: index 1 is 1, not above the one before (2): they must increase strictly"},
        {"repeated", {1, 1}, 5123, nullptr, "sparse.indices: index 1 is 1, not above the one before (1): they must increase strictly"},
        {"past count", {1, 4}, 5125, nullptr, "sparse.indices: index 1 is 4, out of range (count 4)"},
        {"count 0", {1}, 5121, [](Json& s, Json&) { s["count"] = 0; }, "sparse.count 0 is not between 1 and the accessor's count (4)"},
        {"count 5", {1}, 5121, [](Json& s, Json&) { s["count"] = 5; }, "sparse.count 5 is not between 1 and the accessor's count (4)"},
        {"float indices", {1}, 5121, [](Json& s, Json&) { s["indices"]["componentType"] = 5126; },
         "sparse.indices.componentType FLOAT (5126), expected UNSIGNED_BYTE (5121), UNSIGNED_SHORT (5123) or UNSIGNED_INT (5125)"},
        {"indices short", {1, 2}, 5123, [](Json& s, Json&) { s["indices"]["byteOffset"] = 2; },
         "sparse.indices: 2 indices need 6 bytes of bufferView 1, which has 4"},
        {"values short", {1, 2}, 5121, [](Json& s, Json&) { s["values"]["byteOffset"] = 4; },
         "sparse.values: 2 values need 28 bytes of bufferView 2, which has 24"},
        {"no such view", {1}, 5121, [](Json& s, Json&) { s["values"]["bufferView"] = 9; },
         "sparse.values: 1 values: bufferView 9 does not exist"},
        {"strided", {1}, 5121, [](Json&, Json& views) { views[2]["byteStride"] = 12; },
         "sparse.values: 1 values: bufferView 2 has a byteStride, which the data of a sparse accessor must not have"},
    };
    for (const auto& c : cases) {
        SCOPED_TRACE(c.name);
        GltfFile f;
        const int positions = f.positions(kSquare);
        Points values(c.at.size(), {0.5f, 0.5f, 0});
        Json s = sparse(f, c.at, values, c.index_type);
        f.primitive({{"attributes", {{"POSITION", positions}}}});
        Json m = Json::parse(f.gltf());
        if (c.change) c.change(s, m["bufferViews"]);
        m["accessors"][0]["sparse"] = s;
        write("m.gltf", m.dump());
        expect_mesh_error(error_for("m.gltf"), "m.gltf", accessor + c.problem);
    }
}

TEST_F(GltfAccessors, ZerosWithoutABufferViewAreCapped) {
    // Nothing in the file backs such a count: 2^24 + 1 would be 200 MB of zeros from 300 bytes.
    GltfFile f;
    f.view(std::string(4, '\0'));  // tinygltf refuses an empty buffer
    const int positions = f.accessor({{"componentType", 5126}, {"count", (1 << 24) + 1}, {"type", "VEC3"}});
    f.primitive({{"attributes", {{"POSITION", positions}}}});
    write("m.gltf", f.gltf());
    expect_mesh_error(error_for("m.gltf"), "m.gltf",
                      "accessor 0 (POSITION of mesh 0 primitive 0): count 16777217 without a bufferView: more than 2^24 elements of zeros");
}

}  // namespace
