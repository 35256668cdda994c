// The mesh_file shape: the same triangles as inline, transforms, normals, degenerate triangles,
// material names, and the shape's own keys.

#include <cmath>
#include <cstdio>
#include <cstring>

#include <glm/geometric.hpp>

#include "import_test_files.h"

namespace {

using wt::SceneDescription;
using wt::TriangleMesh;
using wt::test::binary_ply;
using wt::test::Bytes;
using wt::test::expect_mesh_error;
using Triangles = std::vector<std::array<uint32_t, 3>>;

using MeshFile = wt::test::ImportTest;

// Floats printed with 9 significant digits read back as the same float.
std::string nine_digits(float v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.9g", double(v));
    return text;
}

void expect_vec3_near(const glm::vec3& actual, const glm::vec3& expected, float tolerance = 1e-5f) {
    EXPECT_NEAR(actual.x, expected.x, tolerance);
    EXPECT_NEAR(actual.y, expected.y, tolerance);
    EXPECT_NEAR(actual.z, expected.z, tolerance);
}

// A PLY (ASCII) of the given triangles and, if any, normals.
std::string ascii_ply(const std::vector<glm::vec3>& vertices, const Triangles& triangles,
                      const std::vector<glm::vec3>& normals = {}) {
    std::string text = "ply\nformat ascii 1.0\nelement vertex " + std::to_string(vertices.size()) +
                       "\nproperty float x\nproperty float y\nproperty float z\n";
    if (!normals.empty()) text += "property float nx\nproperty float ny\nproperty float nz\n";
    text += "element face " + std::to_string(triangles.size()) + "\nproperty list uchar int vertex_indices\nend_header\n";
    for (std::size_t v = 0; v < vertices.size(); ++v) {
        text += nine_digits(vertices[v].x) + " " + nine_digits(vertices[v].y) + " " + nine_digits(vertices[v].z);
        if (!normals.empty())
            text += " " + nine_digits(normals[v].x) + " " + nine_digits(normals[v].y) + " " + nine_digits(normals[v].z);
        text += "\n";
    }
    for (const auto& t : triangles) text += "3 " + std::to_string(t[0]) + " " + std::to_string(t[1]) + " " + std::to_string(t[2]) + "\n";
    return text;
}

// ---------------------------------------------------------------------------------------------
// Same triangles as inline

struct RandomMesh {
    std::vector<glm::vec3> vertices;
    Triangles triangles;
};

RandomMesh random_mesh() {
    RandomMesh m;
    uint32_t state = 12345;
    const auto next = [&] {
        state = state * 1664525u + 1013904223u;
        return float(state >> 8) / float(1 << 24);
    };
    for (int v = 0; v < 300; ++v) m.vertices.push_back({next() * 20 - 10, next() * 0.002f - 0.001f, next() * 3e4f});
    for (uint32_t t = 0; t + 2 < 300; ++t) m.triangles.push_back({t, t + 1, t + 2});
    return m;
}

TEST_F(MeshFile, SameVerticesBitForBitAsInline) {
    const RandomMesh m = random_mesh();
    std::string inline_vertices, obj;
    for (const glm::vec3& v : m.vertices) {
        inline_vertices += std::string(inline_vertices.empty() ? "" : ", ") + "[" + nine_digits(v.x) + ", " +
                           nine_digits(v.y) + ", " + nine_digits(v.z) + "]";
        obj += "v " + nine_digits(v.x) + " " + nine_digits(v.y) + " " + nine_digits(v.z) + "\n";
    }
    std::string inline_triangles;
    std::vector<std::vector<int32_t>> faces;
    for (const auto& t : m.triangles) {
        inline_triangles += std::string(inline_triangles.empty() ? "" : ", ") + "[" + std::to_string(t[0]) + ", " +
                            std::to_string(t[1]) + ", " + std::to_string(t[2]) + "]";
        obj += "f " + std::to_string(t[0] + 1) + " " + std::to_string(t[1] + 1) + " " + std::to_string(t[2] + 1) + "\n";
        faces.push_back({int32_t(t[0]), int32_t(t[1]), int32_t(t[2])});
    }
    const std::string inline_shape = R"({"type": "mesh", "material": "white", "vertices": [)" + inline_vertices +
                                     R"(], "triangles": [)" + inline_triangles + "]}";
    const TriangleMesh reference = load(inline_shape).meshes[0];

    // The inline floats are what the binary files store.
    std::vector<std::array<float, 3>> floats;
    for (const glm::vec3& v : reference.vertices) floats.push_back({v.x, v.y, v.z});
    Bytes positions, indices;
    for (const auto& f : floats) positions.put(f[0]).put(f[1]).put(f[2]);
    for (const auto& t : m.triangles) indices.put(t[0]).put(t[1]).put(t[2]);
    const std::size_t vbytes = positions.str().size(), ibytes = indices.str().size();
    const std::string gltf_json =
        R"({"asset": {"version": "2.0"}, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
            "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
            "buffers": [{"byteLength": )" + std::to_string(vbytes + ibytes) + R"(}],
            "bufferViews": [{"buffer": 0, "byteLength": )" + std::to_string(vbytes) + R"(},
                            {"buffer": 0, "byteOffset": )" + std::to_string(vbytes) + R"(, "byteLength": )" +
        std::to_string(ibytes) + R"(}],
            "accessors": [{"bufferView": 0, "componentType": 5126, "count": 300, "type": "VEC3"},
                          {"bufferView": 1, "componentType": 5125, "count": )" + std::to_string(3 * m.triangles.size()) +
        R"(, "type": "SCALAR"}]})";

    write("m.obj", obj);
    write("ascii.ply", ascii_ply(m.vertices, m.triangles));
    write("le.ply", binary_ply(false, floats, faces));
    write("be.ply", binary_ply(true, floats, faces));
    write("m.glb", wt::test::glb(gltf_json, positions.str() + indices.str()));
    for (const char* file : {"m.obj", "ascii.ply", "le.ply", "be.ply", "m.glb"}) {
        SCOPED_TRACE(file);
        const SceneDescription scene = load_file(file);
        ASSERT_EQ(scene.meshes.size(), 1u);
        const TriangleMesh& mesh = scene.meshes[0];
        ASSERT_EQ(mesh.vertices.size(), reference.vertices.size());
        EXPECT_EQ(std::memcmp(mesh.vertices.data(), reference.vertices.data(), sizeof(glm::vec3) * mesh.vertices.size()), 0);
        for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
            if (std::memcmp(&mesh.vertices[v], &reference.vertices[v], sizeof(glm::vec3)) != 0) {
                ADD_FAILURE() << "vertex " << v << " differs: " << nine_digits(mesh.vertices[v].x) << " "
                              << nine_digits(mesh.vertices[v].y) << " " << nine_digits(mesh.vertices[v].z);
                break;
            }
        EXPECT_EQ(mesh.triangles, reference.triangles);
        EXPECT_EQ(mesh.material, reference.material);
        EXPECT_TRUE(scene.notes.empty());
    }
}

// ---------------------------------------------------------------------------------------------
// Transforms

const std::vector<glm::vec3> kTriangle{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};

TEST_F(MeshFile, ScaleThenRotateThenTranslate) {
    write("t.ply", ascii_ply(kTriangle, {{0, 1, 2}}));
    const TriangleMesh mesh =
        load_file("t.ply", R"(, "transform": {"translate": [1, 2, 3], "rotate": {"axis": [0, 0, 1], "degrees": 90}, "scale": 2})")
            .meshes[0];
    // (1,0,0) -> (2,0,0) -> (0,2,0) -> (1,4,3); (0,1,0) -> (0,2,0) -> (-2,0,0) -> (-1,2,3).
    expect_vec3_near(mesh.vertices[0], {1, 4, 3});
    expect_vec3_near(mesh.vertices[1], {-1, 2, 3});
    expect_vec3_near(mesh.vertices[2], {1, 2, 5});
}

TEST_F(MeshFile, NonUniformScaleAndTranslateOnly) {
    write("t.ply", ascii_ply(kTriangle, {{0, 1, 2}}));
    const TriangleMesh scaled = load_file("t.ply", R"(, "transform": {"scale": [2, 3, 4]})").meshes[0];
    EXPECT_EQ(scaled.vertices, (std::vector<glm::vec3>{{2, 0, 0}, {0, 3, 0}, {0, 0, 4}}));
    const TriangleMesh moved = load_file("t.ply", R"(, "transform": {"translate": [0.5, 0, -1]})").meshes[0];
    EXPECT_EQ(moved.vertices, (std::vector<glm::vec3>{{1.5f, 0, -1}, {0.5f, 1, -1}, {0.5f, 0, 0}}));
}

TEST_F(MeshFile, MatrixIsRowsAsWritten) {
    write("t.ply", ascii_ply(kTriangle, {{0, 1, 2}}));
    // The same as scale 2, rotate 90 about z, translate (1, 2, 3).
    const TriangleMesh mesh =
        load_file("t.ply", R"(, "transform": {"matrix": [[0, -2, 0, 1], [2, 0, 0, 2], [0, 0, 2, 3], [0, 0, 0, 1]]})").meshes[0];
    EXPECT_EQ(mesh.vertices, (std::vector<glm::vec3>{{1, 4, 3}, {-1, 2, 3}, {1, 2, 5}}));
}

TEST_F(MeshFile, NormalsUnderNonUniformScaleStayPerpendicular) {
    // The plane x + y = 1 (z free), its normal (1, 1, 0) / sqrt 2 given by the file.
    const std::vector<glm::vec3> vertices{{1, 0, 0}, {0, 1, 0}, {1, 0, 1}};
    const glm::vec3 n = glm::normalize(glm::vec3(1, 1, 0));
    write("p.ply", ascii_ply(vertices, {{0, 1, 2}}, {n, n, n}));
    const TriangleMesh mesh = load_file("p.ply", R"(, "transform": {"scale": [2, 1, 1]})").meshes[0];
    // x/2 + y = 1: normal along (1/2, 1, 0); transforming the normal like a point would give (2, 1, 0).
    const glm::vec3 expected = glm::normalize(glm::vec3(0.5f, 1, 0));
    ASSERT_EQ(mesh.normals.size(), 3u);
    for (const glm::vec3& shading : mesh.normals) {
        expect_vec3_near(shading, expected);
        EXPECT_NEAR(glm::length(shading), 1.0f, 1e-6f);
        EXPECT_NEAR(glm::dot(shading, mesh.vertices[1] - mesh.vertices[0]), 0.0f, 1e-6f);
    }
}

TEST_F(MeshFile, AMirroringTransformKeepsTheFrontFaceWithTheNormals) {
    const glm::vec3 n(0, 0, 1);
    write("t.ply", ascii_ply({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}}, {n, n, n}));
    const TriangleMesh plain = load_file("t.ply").meshes[0];
    const TriangleMesh mirrored = load_file("t.ply", R"(, "transform": {"scale": [-1, 1, 1]})").meshes[0];
    const auto geometric = [](const TriangleMesh& m) {
        const auto& t = m.triangles[0];
        return glm::cross(m.vertices[t[1]] - m.vertices[t[0]], m.vertices[t[2]] - m.vertices[t[0]]);
    };
    EXPECT_GT(glm::dot(geometric(plain), plain.normals[0]), 0.0f);
    EXPECT_EQ(mirrored.triangles[0], (std::array<uint32_t, 3>{0, 2, 1}));  // winding reversed
    EXPECT_GT(glm::dot(geometric(mirrored), mirrored.normals[0]), 0.0f);
}

// ---------------------------------------------------------------------------------------------
// Normals

TEST_F(MeshFile, SmoothNormalsAreAngleWeighted) {
    // The corner of a box at the origin: the x = 0 face as two triangles, y = 0 and z = 0 as one
    // each, all wound to face the origin's outside (-x, -y, -z). Angle weights give each face
    // its 90 degrees; an unweighted average would count the x face twice.
    const std::vector<glm::vec3> v{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, 1, 1}};
    write("corner.ply", ascii_ply(v, {{0, 3, 4}, {0, 4, 2}, {0, 1, 3}, {0, 2, 1}}));
    const TriangleMesh mesh = load_file("corner.ply", R"(, "normals": "smooth")").meshes[0];
    ASSERT_EQ(mesh.normals.size(), 5u);
    expect_vec3_near(mesh.normals[0], -glm::normalize(glm::vec3(1, 1, 1)), 1e-6f);
    const glm::vec3 unweighted = -glm::normalize(glm::vec3(2, 1, 1));
    EXPECT_GT(glm::length(mesh.normals[0] - unweighted), 0.1f);
    // Vertex 4 is only on the x face.
    expect_vec3_near(mesh.normals[4], {-1, 0, 0}, 1e-6f);
}

TEST_F(MeshFile, AZeroFileNormalIsReplacedByTheSmoothOne) {
    const glm::vec3 up(0, 0, 3);
    write("z.ply", ascii_ply({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}}, {up, glm::vec3(0), up}));
    const TriangleMesh mesh = load_file("z.ply", R"(, "transform": {"rotate": {"axis": [1, 0, 0], "degrees": 90}})").meshes[0];
    ASSERT_EQ(mesh.normals.size(), 3u);
    for (const glm::vec3& n : mesh.normals) expect_vec3_near(n, {0, -1, 0}, 1e-6f);  // +z turned about x
}

TEST_F(MeshFile, FlatIgnoresTheFileNormalsAndFileIsTheDefault) {
    const glm::vec3 n(0, 0, 1);
    write("t.ply", ascii_ply(kTriangle, {{0, 1, 2}}, {n, n, n}));
    EXPECT_EQ(load_file("t.ply").meshes[0].normals.size(), 3u);
    EXPECT_EQ(load_file("t.ply", R"(, "normals": "file")").meshes[0].normals.size(), 3u);
    EXPECT_TRUE(load_file("t.ply", R"(, "normals": "flat")").meshes[0].normals.empty());
    write("bare.ply", ascii_ply(kTriangle, {{0, 1, 2}}));
    EXPECT_TRUE(load_file("bare.ply").meshes[0].normals.empty());
    EXPECT_EQ(load_file("bare.ply", R"(, "normals": "smooth")").meshes[0].normals.size(), 3u);
}

// ---------------------------------------------------------------------------------------------
// Degenerate triangles, materials, paths

TEST_F(MeshFile, DegenerateTrianglesAreDroppedAndCounted) {
    const std::vector<glm::vec3> v{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {2, 0, 0}};
    write("d.ply", ascii_ply(v, {{0, 1, 2}, {0, 1, 1}, {0, 1, 3}}));  // repeated index; collinear
    const SceneDescription scene = load_file("d.ply");
    EXPECT_EQ(scene.meshes[0].triangles, (Triangles{{0, 1, 2}}));
    ASSERT_EQ(scene.notes.size(), 1u);
    EXPECT_NE(scene.notes[0].find("shapes[0].file: "), std::string::npos) << scene.notes[0];
    EXPECT_NE(scene.notes[0].find("dropped 2 degenerate (zero-area) triangles of 3"), std::string::npos) << scene.notes[0];
}

TEST_F(MeshFile, OnlyDegenerateTrianglesIsAnError) {
    write("d.ply", ascii_ply({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}}, {{0, 1, 2}}));
    expect_mesh_error(error_for("d.ply"), "d.ply", "every triangle is degenerate (zero area)");
}

TEST_F(MeshFile, PathIsRelativeToTheSceneFile) {
    write("models/t.ply", ascii_ply(kTriangle, {{0, 1, 2}}));
    EXPECT_EQ(load_file("models/t.ply").meshes[0].vertices, kTriangle);
    write("scene.json", scene_text(R"({"type": "mesh_file", "file": "models/t.ply", "material": "lamp"})"));
    const SceneDescription scene = wt::load_scene_file(path("scene.json"));
    EXPECT_EQ(scene.meshes[0].material, 1u);
    EXPECT_TRUE(scene.materials[1].is_emissive());
}

TEST_F(MeshFile, TheSameFileTwiceSharesItsMaterialsAndTheSceneCanOverrideOne) {
    write("m.mtl", "newmtl red\nKd 0.8 0.1 0.1\nnewmtl blue\nKd 0.1 0.1 0.8\n");
    write("m.obj", "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl red\nf 1 2 3\nusemtl blue\nf 1 3 2\n");
    const std::string shape = R"({"type": "mesh_file", "file": "m.obj", "material": "from_file"})";
    const SceneDescription scene = load(shape + ", " + shape,
                                        R"({"white": {"type": "lambertian", "albedo": [0.5, 0.5, 0.5]},
                                            "m.obj/blue": {"type": "mirror"}})");
    ASSERT_EQ(scene.materials.size(), 3u);  // white, m.obj/blue (the scene's), m.obj/red
    EXPECT_EQ(scene.materials[2].name, "m.obj/red");
    ASSERT_EQ(scene.meshes.size(), 4u);
    EXPECT_EQ(scene.meshes[0].material, 2u);
    EXPECT_EQ(scene.meshes[1].material, 1u);
    EXPECT_EQ(scene.materials[1].type, wt::MaterialType::mirror);
    EXPECT_EQ(scene.meshes[2].material, 2u);
    EXPECT_EQ(scene.meshes[3].material, 1u);
}

// ---------------------------------------------------------------------------------------------
// The shape's keys

class MeshFileKeys : public MeshFile {
protected:
    void SetUp() override {
        MeshFile::SetUp();
        write("t.ply", ascii_ply(kTriangle, {{0, 1, 2}}));
    }
    std::string shape_error(const std::string& shape) const {
        try {
            load(shape);
        } catch (const wt::SceneError& e) {
            return e.what();
        }
        ADD_FAILURE() << "no SceneError for " << shape;
        return "";
    }
    void expect(const std::string& keys, const std::string& message) {
        const std::string shape = R"({"type": "mesh_file", "file": "t.ply", "material": "white")" + keys + "}";
        const std::string got = shape_error(shape);
        EXPECT_NE(got.find("scene.json: " + message), std::string::npos) << got << "\nexpected: " << message;
    }
};

TEST_F(MeshFileKeys, UnknownKey) { expect(R"(, "scale": 2)", "shapes[0].scale: unknown key for a mesh_file (allowed: type, file, material, transform, normals)"); }
TEST_F(MeshFileKeys, FileNotAString) {
    EXPECT_NE(shape_error(R"({"type": "mesh_file", "file": 3, "material": "white"})").find("shapes[0].file: expected a string, got 3"), std::string::npos);
}
TEST_F(MeshFileKeys, FileMissing) {
    EXPECT_NE(shape_error(R"({"type": "mesh_file", "material": "white"})").find("shapes[0].file: required key is missing"), std::string::npos);
}
TEST_F(MeshFileKeys, UnknownMaterial) {
    const std::string got = shape_error(R"({"type": "mesh_file", "file": "t.ply", "material": "fromfile"})");
    EXPECT_NE(got.find("shapes[0].material: no material named \"fromfile\""), std::string::npos) << got;
}
TEST_F(MeshFileKeys, NormalsChoice) { expect(R"(, "normals": "soft")", R"(shapes[0].normals: must be one of "file", "smooth", "flat", got string "soft")"); }
TEST_F(MeshFileKeys, TransformUnknownKey) { expect(R"(, "transform": {"shift": [1, 0, 0]})", "shapes[0].transform.shift: unknown key"); }
TEST_F(MeshFileKeys, MatrixWithOthers) { expect(R"(, "transform": {"matrix": [[1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]], "scale": 2})", "shapes[0].transform.scale: unknown key next to \"matrix\""); }
TEST_F(MeshFileKeys, ZeroScale) { expect(R"(, "transform": {"scale": [1, 0, 1]})", "shapes[0].transform.scale: must be non-zero"); }
TEST_F(MeshFileKeys, SingularMatrix) { expect(R"(, "transform": {"matrix": [[1,0,0,0],[1,0,0,0],[0,0,1,0],[0,0,0,1]]})", "shapes[0].transform.matrix: is singular"); }
TEST_F(MeshFileKeys, ProjectiveMatrix) { expect(R"(, "transform": {"matrix": [[1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,1,1]]})", "shapes[0].transform.matrix[3]: the last row must be [0, 0, 0, 1]"); }
TEST_F(MeshFileKeys, MatrixShape) { expect(R"(, "transform": {"matrix": [1, 0, 0, 0]})", "shapes[0].transform.matrix[0]: expected a row of 4 numbers, got 1"); }
TEST_F(MeshFileKeys, RotationAxisZero) { expect(R"(, "transform": {"rotate": {"axis": [0, 0, 0], "degrees": 5}})", "shapes[0].transform.rotate.axis: must be non-zero"); }
TEST_F(MeshFileKeys, RotationDegreesMissing) { expect(R"(, "transform": {"rotate": {"axis": [0, 0, 1]}})", "shapes[0].transform.rotate.degrees: required key is missing"); }

}  // namespace
