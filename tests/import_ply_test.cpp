// PLY files through the scene loader: ASCII and binary of both byte orders, polygons, normals,
// and every kind of bad input, each named by line (ASCII) or byte offset (binary).

#include "import_test_files.h"

namespace {

using wt::SceneDescription;
using wt::TriangleMesh;
using wt::test::binary_ply;
using wt::test::expect_mesh_error;
using Triangles = std::vector<std::array<uint32_t, 3>>;

using PlyImport = wt::test::ImportTest;

// A square and a triangle, with normals; vertex 4 is off the square's plane.
const std::vector<std::array<float, 3>> kVertices{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5f, 0.25f, 1}};
const std::vector<std::array<float, 3>> kNormals{{0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {0, -0.6f, 0.8f}};
const std::vector<std::vector<int32_t>> kFaces{{0, 1, 2, 3}, {0, 1, 4}};

const std::string kAsciiPly = R"(ply
format ascii 1.0
comment a square and a triangle
element vertex 5
property float x
property float y
property float z
property float nx
property float ny
property float nz
element face 2
property list uchar int vertex_indices
end_header
0 0 0 0 0 1
1 0 0 0 0 1
1 1 0 0 0 1
0 1 0 0 0 1
0.5 0.25 1 0 -0.6 0.8
4 0 1 2 3
3 0 1 4
)";

void expect_square_and_triangle(const SceneDescription& scene) {
    ASSERT_EQ(scene.meshes.size(), 1u);
    const TriangleMesh& mesh = scene.meshes[0];
    ASSERT_EQ(mesh.vertices.size(), 5u);
    for (std::size_t v = 0; v < 5; ++v) EXPECT_EQ(mesh.vertices[v], glm::vec3(kVertices[v][0], kVertices[v][1], kVertices[v][2]));
    EXPECT_EQ(mesh.triangles, (Triangles{{0, 1, 2}, {0, 2, 3}, {0, 1, 4}}));
    ASSERT_EQ(mesh.normals.size(), 5u);
    EXPECT_EQ(mesh.normals[0], glm::vec3(0, 0, 1));
    EXPECT_NEAR(mesh.normals[4].y, -0.6f, 1e-7f);
    EXPECT_NEAR(mesh.normals[4].z, 0.8f, 1e-7f);
}

TEST_F(PlyImport, Ascii) {
    write("m.ply", kAsciiPly);
    expect_square_and_triangle(load_file("m.ply"));
}

TEST_F(PlyImport, BinaryLittleEndian) {
    write("m.ply", binary_ply(false, kVertices, kFaces, kNormals));
    expect_square_and_triangle(load_file("m.ply"));
}

TEST_F(PlyImport, BinaryBigEndian) {
    write("m.ply", binary_ply(true, kVertices, kFaces, kNormals));
    expect_square_and_triangle(load_file("m.ply"));
}

TEST_F(PlyImport, CrLfLinesAndOtherElementsAndPropertiesAreRead) {
    std::string text = R"(ply
format ascii 1.0
element vertex 3
property double x
property uchar red
property double y
property double z
property list uchar float extra
element material 1
property float shine
element face 1
property uint flags
property list uchar uint vertex_index
end_header
0 255 0 0 2 9 9
1 0 0 0 0
0 7 1 0 1 3.5
0.25
17 3 0 1 2
)";
    std::string crlf;
    for (char c : text) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
    write("m.ply", crlf);
    const SceneDescription scene = load_file("m.ply");
    ASSERT_EQ(scene.meshes.size(), 1u);
    EXPECT_EQ(scene.meshes[0].vertices, (std::vector<glm::vec3>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}));
    EXPECT_EQ(scene.meshes[0].triangles, (Triangles{{0, 1, 2}}));
    EXPECT_TRUE(scene.meshes[0].normals.empty());
}

// Every binary type, in both byte orders, as coordinates, skipped properties, a list's count and
// its items: each is read at its own size, and a wrong size would shift every later value.
TEST_F(PlyImport, EveryBinaryTypeInBothByteOrders) {
    for (const bool big_endian : {false, true}) {
        wt::test::Bytes b(big_endian);
        b.text(std::string("ply\nformat ") + (big_endian ? "binary_big_endian" : "binary_little_endian") + " 1.0\n");
        b.text("element vertex 3\nproperty char x\nproperty ushort y\nproperty double z\nproperty short s\n"
               "property uint u\nproperty float f\nproperty list int uchar skipped\n");
        b.text("element face 2\nproperty int8 flag\nproperty list ushort uint16 vertex_indices\nend_header\n");
        const int8_t x[3] = {-3, 0, 127};
        const uint16_t y[3] = {65535, 0, 2};
        const double z[3] = {0.125, -1e10, 3.0};
        for (int v = 0; v < 3; ++v) {
            b.put(x[v]).put(y[v]).put(z[v]).put(int16_t(-32768 + v)).put(uint32_t(0xfffffff0u + uint32_t(v))).put(float(v) * 0.5f);
            b.put(int32_t(v));  // the skipped list: v uchar items
            for (int k = 0; k < v; ++k) b.put(uint8_t(200 + k));
        }
        b.put(int8_t(-1)).put(uint16_t(3)).put(uint16_t(2)).put(uint16_t(1)).put(uint16_t(0));
        b.put(int8_t(5)).put(uint16_t(4)).put(uint16_t(0)).put(uint16_t(1)).put(uint16_t(2)).put(uint16_t(1));
        write("types.ply", b.str());
        const SceneDescription scene = load_file("types.ply");
        ASSERT_EQ(scene.meshes.size(), 1u) << (big_endian ? "big" : "little") << " endian";
        EXPECT_EQ(scene.meshes[0].vertices, (std::vector<glm::vec3>{{-3, 65535, 0.125f}, {0, 0, -1e10f}, {127, 2, 3}}));
        EXPECT_EQ(scene.meshes[0].triangles, (Triangles{{2, 1, 0}, {0, 1, 2}, {0, 2, 1}}));
    }
}

// A file several times the reader's 1 MiB buffer, whose 24-byte vertex records and 17-byte
// faces straddle the buffer's refills: every record as written.
TEST_F(PlyImport, BinaryFileLargerThanTheReadBufferKeepsEveryRecord) {
    constexpr int kSide = 300;  // 90,000 vertices, 2 * 299^2 triangles: about 3.7 MB
    std::vector<std::array<float, 3>> vertices, normals;
    for (int j = 0; j < kSide; ++j)
        for (int i = 0; i < kSide; ++i) {
            vertices.push_back({float(i), float(j), float((i * 7 + j * 13) % 11) * 0.25f});
            normals.push_back({0.0f, 0.6f, 0.8f});
        }
    std::vector<std::vector<int32_t>> faces;
    for (int j = 0; j + 1 < kSide; ++j)
        for (int i = 0; i + 1 < kSide; ++i) {
            const int32_t a = j * kSide + i;
            faces.push_back({a, a + 1, a + 1 + kSide, a + kSide});
        }
    for (const bool big_endian : {false, true}) {
        write("big.ply", binary_ply(big_endian, vertices, faces, normals));
        const SceneDescription scene = load_file("big.ply");
        ASSERT_EQ(scene.meshes.size(), 1u);
        const TriangleMesh& mesh = scene.meshes[0];
        ASSERT_EQ(mesh.vertices.size(), vertices.size());
        ASSERT_EQ(mesh.triangles.size(), 2 * faces.size());
        for (std::size_t v = 0; v < vertices.size(); ++v)
            ASSERT_EQ(mesh.vertices[v], glm::vec3(vertices[v][0], vertices[v][1], vertices[v][2])) << "vertex " << v;
        for (std::size_t f = 0; f < faces.size(); ++f) {
            const auto& q = faces[f];
            ASSERT_EQ(mesh.triangles[2 * f], (std::array<uint32_t, 3>{uint32_t(q[0]), uint32_t(q[1]), uint32_t(q[2])})) << "face " << f;
            ASSERT_EQ(mesh.triangles[2 * f + 1], (std::array<uint32_t, 3>{uint32_t(q[0]), uint32_t(q[2]), uint32_t(q[3])})) << "face " << f;
        }
        ASSERT_EQ(mesh.normals.size(), vertices.size());
        EXPECT_NEAR(mesh.normals.back().z, 0.8f, 1e-6f);
    }
}

// ---------------------------------------------------------------------------------------------
// Bad input

std::string ascii_with(const std::string& from, const std::string& to) {
    std::string text = kAsciiPly;
    const std::size_t at = text.find(from);
    if (at == std::string::npos) ADD_FAILURE() << "test bug: " << from;
    return text.replace(at, from.size(), to);
}

TEST_F(PlyImport, AHeaderLineThatIsNotPlyIsSkippedWithANote) {
    // Blender 2.4 wrote "Created by ..." without "comment" (assimp-testmodels' Wuson.ply).
    write("one.ply", ascii_with("comment a square and a triangle", "Created by Blender3D 247 - www.blender.org, source file: "));
    const SceneDescription one = load_file("one.ply");
    expect_square_and_triangle(one);
    ASSERT_EQ(one.notes.size(), 1u);
    EXPECT_NE(one.notes[0].find("scene.json: shapes[0].file: " + path("one.ply") +
                                ": skipped a header line that is not PLY, line 3: \"Created by Blender3D 247"),
              std::string::npos)
        << one.notes[0];
    // Binary too; several such lines are one note, naming the first.
    std::string binary = binary_ply(false, kVertices, kFaces, kNormals);
    binary.replace(binary.find("comment written"), 15, "Written");
    binary.insert(binary.find("element face"), "obj_info fine\n" + std::string(200, 'x') + "\n");
    write("two.ply", binary);
    const SceneDescription two = load_file("two.ply");
    expect_square_and_triangle(two);
    ASSERT_EQ(two.notes.size(), 1u);
    EXPECT_NE(two.notes[0].find("skipped 2 header lines that are not PLY, the first line 3: \"Written by the wavetrace tests\""),
              std::string::npos)
        << two.notes[0];
    // What looks like the layout stays an error.
    write("bad.ply", ascii_with("element face 2", "element face two"));
    expect_mesh_error(error_for("bad.ply"), "bad.ply:11: malformed element line: \"element face two\"", "");
}

TEST_F(PlyImport, MalformedNumberNamesTheLine) {
    write("bad.ply", ascii_with("1 1 0 0 0 1", "1 abc 0 0 0 1"));
    expect_mesh_error(error_for("bad.ply"), "bad.ply:16: not a number: \"abc\"", "");
}

TEST_F(PlyImport, TooFewAndTooManyValuesNameTheLine) {
    write("few.ply", ascii_with("1 1 0 0 0 1", "1 1 0 0 0"));
    expect_mesh_error(error_for("few.ply"), "few.ply:16: too few values", "");
    write("many.ply", ascii_with("3 0 1 4", "3 0 1 4 7"));
    expect_mesh_error(error_for("many.ply"), "many.ply:20: extra values at the end of the line", "");
}

TEST_F(PlyImport, AsciiFileEndingEarly) {
    write("short.ply", ascii_with("3 0 1 4\n", ""));
    expect_mesh_error(error_for("short.ply"), "short.ply:", "the file ends before face 1");
}

TEST_F(PlyImport, TruncatedBinaryNamesTheByteOffset) {
    const std::string whole = binary_ply(false, kVertices, kFaces);
    const std::size_t header = whole.find("end_header\n") + 11;
    // Cut inside face 1: it starts after 5 vertices of 12 bytes and face 0 (1 + 4 * 4 bytes).
    const std::size_t face1 = header + 5 * 12 + 17;
    write("cut.ply", whole.substr(0, face1 + 6));
    expect_mesh_error(error_for("cut.ply"), "cut.ply: byte " + std::to_string(face1) + " (face 1): the file ends inside this record", "");
}

TEST_F(PlyImport, EveryTruncatedFileIsAnError) {
    for (const bool big_endian : {false, true}) {
        const std::string whole = binary_ply(big_endian, kVertices, kFaces, kNormals);
        for (std::size_t n = 0; n < whole.size(); ++n) {
            write("cut.ply", whole.substr(0, n));
            EXPECT_NE(error_for("cut.ply").find("cut.ply"), std::string::npos) << n << " bytes";
        }
    }
    for (std::size_t n = 0; n + 1 < kAsciiPly.size(); ++n) {
        if (kAsciiPly[n] == '\n') continue;  // cut at a line end: the last record may still be whole
        write("cut.ply", kAsciiPly.substr(0, n));
        try {
            load_file("cut.ply");
        } catch (const wt::SceneError&) {
            continue;
        }
        // Only a cut inside the last number can leave a valid file (a shorter index).
        EXPECT_GT(n, kAsciiPly.size() - 3) << n << " bytes loaded";
    }
}

TEST_F(PlyImport, IndexOutOfRange) {
    write("bad.ply", binary_ply(true, kVertices, {{0, 1, 5}}));
    expect_mesh_error(error_for("bad.ply"), "bad.ply: byte", "(face 0): vertex index 5 out of range (the file has 5 vertices)");
    write("neg.ply", ascii_with("3 0 1 4", "3 0 -1 4"));
    expect_mesh_error(error_for("neg.ply"), "neg.ply:20: vertex index -1 out of range", "");
}

// An ASCII number beyond its column's declared type (the fuzzer's list length of 3e29 as a
// uchar) is an error naming the line and the type, not a conversion out of range.
TEST_F(PlyImport, AsciiIntegerOutOfItsTypesRangeNamesTheLine) {
    write("count.ply", ascii_with("3 0 1 4", "333333333333333333333333333330 0 1 4"));
    expect_mesh_error(error_for("count.ply"), "count.ply:20: \"333333333333333333333333333330\" is out of range for its type, uchar", "");
    write("uchar.ply", ascii_with("3 0 1 4", "256 0 1 4"));
    expect_mesh_error(error_for("uchar.ply"), "uchar.ply:20: \"256\" is out of range for its type, uchar", "");
    write("index.ply", ascii_with("3 0 1 4", "3 0 1 4294967296"));
    expect_mesh_error(error_for("index.ply"), "index.ply:20: \"4294967296\" is out of range for its type, int", "");
    // A float-typed index is allowed, and one far out of range is reported as it is written.
    std::string floats = ascii_with("3 0 1 4", "3 0 1 1e30");
    floats.replace(floats.find("list uchar int"), 14, "list uchar float");
    write("float.ply", floats);
    expect_mesh_error(error_for("float.ply"), "float.ply:20: vertex index 1e+30 out of range (the file has 5 vertices)", "");
    // The largest value of the type is read: 255 is a list length a uchar holds (and then the
    // line has too few indices, the next check's error).
    write("max.ply", ascii_with("3 0 1 4", "255 0 1 4"));
    expect_mesh_error(error_for("max.ply"), "max.ply:20: too few values", "");
}

TEST_F(PlyImport, FaceWithTwoVertices) {
    write("bad.ply", ascii_with("3 0 1 4", "2 0 1"));
    expect_mesh_error(error_for("bad.ply"), "bad.ply:20: a face needs at least 3 vertices, got 2", "");
}

TEST_F(PlyImport, NanVertex) {
    auto vertices = kVertices;
    vertices[3][1] = std::numeric_limits<float>::quiet_NaN();
    write("nan.ply", binary_ply(false, vertices, kFaces));
    expect_mesh_error(error_for("nan.ply"), "nan.ply: byte", "(vertex 3): vertex position is not finite");
    write("inf.ply", ascii_with("1 1 0 0 0 1", "1 inf 0 0 0 1"));
    expect_mesh_error(error_for("inf.ply"), "inf.ply:16: vertex position is not finite", "");
}

TEST_F(PlyImport, NoFacesIsAnEmptyMesh) {
    write("empty.ply", binary_ply(false, kVertices, {}));
    expect_mesh_error(error_for("empty.ply"), "empty.ply", "no triangles (an empty mesh)");
}

TEST_F(PlyImport, BadHeaders) {
    write("magic.ply", "plx\n");
    expect_mesh_error(error_for("magic.ply"), "magic.ply:1: not a PLY file", "");
    write("format.ply", ascii_with("format ascii 1.0", "format binary_middle_endian 1.0"));
    expect_mesh_error(error_for("format.ply"), "format.ply:2: unknown format \"binary_middle_endian\"", "");
    write("type.ply", ascii_with("property float y", "property real y"));
    expect_mesh_error(error_for("type.ply"), "type.ply:6: unknown property type \"real\"", "");
    write("noend.ply", "ply\nformat ascii 1.0\nelement vertex 0\n");
    expect_mesh_error(error_for("noend.ply"), "noend.ply:3: the header ends before end_header", "");
    write("noz.ply", ascii_with("property float z\n", ""));
    expect_mesh_error(error_for("noz.ply"), "noz.ply: the vertex element lacks an x, y or z property", "");
}

}  // namespace
