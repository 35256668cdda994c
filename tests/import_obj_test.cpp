// OBJ files through the scene loader: polygons, negative indices, groups, vn, MTL materials,
// and every kind of bad input.

#include <glm/geometric.hpp>

#include "import_test_files.h"

namespace {

using wt::MaterialType;
using wt::SceneDescription;
using wt::TriangleMesh;
using wt::test::expect_mesh_error;
using Triangles = std::vector<std::array<uint32_t, 3>>;

using ObjImport = wt::test::ImportTest;

const std::string kPentagon = "v 0 0 0\nv 1 0 0\nv 1.5 1 0\nv 0.5 2 0\nv -0.5 1 0\n";

TEST_F(ObjImport, PolygonsBecomeFansAndKeepTheFileOrder) {
    write("p.obj", kPentagon + "f 1 2 3 4 5\n");
    const SceneDescription scene = load_file("p.obj");
    ASSERT_EQ(scene.meshes.size(), 1u);
    const TriangleMesh& mesh = scene.meshes[0];
    EXPECT_EQ(mesh.triangles, (Triangles{{0, 1, 2}, {0, 2, 3}, {0, 3, 4}}));
    ASSERT_EQ(mesh.vertices.size(), 5u);
    EXPECT_EQ(mesh.vertices[2], glm::vec3(1.5f, 1.0f, 0.0f));
    EXPECT_EQ(mesh.material, 0u);  // "white": the scene's material applies to the whole file
    EXPECT_TRUE(mesh.normals.empty());
}

TEST_F(ObjImport, QuadIsTwoTriangles) {
    write("q.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n");
    EXPECT_EQ(load_file("q.obj").meshes[0].triangles, (Triangles{{0, 1, 2}, {0, 2, 3}}));
}

TEST_F(ObjImport, NegativeIndicesCountBackFromTheLastVertex) {
    write("pos.obj", kPentagon + "f 1 2 3\nv 3 3 0\nf 4 5 6\n");
    write("neg.obj", kPentagon + "f -5 -4 -3\nv 3 3 0\nf -3 -2 -1\n");
    const Triangles expected{{0, 1, 2}, {3, 4, 5}};
    EXPECT_EQ(load_file("pos.obj").meshes[0].triangles, expected);
    EXPECT_EQ(load_file("neg.obj").meshes[0].triangles, expected);
}

TEST_F(ObjImport, EveryObjectAndGroupIsLoaded) {
    write("g.obj", kPentagon + "o first\nf 1 2 3\ng second\nf 1 3 4\no third\ng fourth\nf 1 4 5\n");
    const SceneDescription scene = load_file("g.obj");
    ASSERT_EQ(scene.meshes.size(), 1u);
    EXPECT_EQ(scene.meshes[0].triangles, (Triangles{{0, 1, 2}, {0, 2, 3}, {0, 3, 4}}));
}

TEST_F(ObjImport, VertexNormalsBecomeShadingNormals) {
    write("n.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 2\nvn 0 0.6 0.8\nf 1//1 2//2 3//1\n");
    const TriangleMesh mesh = load_file("n.obj").meshes[0];
    ASSERT_EQ(mesh.normals.size(), 3u);
    EXPECT_EQ(mesh.normals[0], glm::vec3(0, 0, 1));  // renormalised
    EXPECT_NEAR(mesh.normals[1].y, 0.6f, 1e-7f);
    EXPECT_NEAR(mesh.normals[1].z, 0.8f, 1e-7f);
    EXPECT_EQ(mesh.normals[2], glm::vec3(0, 0, 1));
}

TEST_F(ObjImport, AVertexGivenTwoNormalsIsSplit) {
    // Two triangles folded along the edge 1-2; each face gives that edge its own normal.
    write("fold.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 1\nvn 0 0 1\nvn 1 0 0\n"
                      "f 1//1 2//1 3//1\nf 2//2 4//2 3//2\n");
    const TriangleMesh mesh = load_file("fold.obj").meshes[0];
    ASSERT_EQ(mesh.vertices.size(), 6u);  // 4 positions, 1 and 2 copied once
    ASSERT_EQ(mesh.normals.size(), 6u);
    EXPECT_EQ(mesh.triangles[0], (std::array<uint32_t, 3>{0, 1, 2}));
    const auto& second = mesh.triangles[1];
    EXPECT_EQ(second[1], 3u);  // position 4 keeps its index: one normal only
    for (uint32_t v : second) EXPECT_EQ(mesh.normals[v], glm::vec3(1, 0, 0));
    for (uint32_t v : mesh.triangles[0]) EXPECT_EQ(mesh.normals[v], glm::vec3(0, 0, 1));
    EXPECT_EQ(mesh.vertices[second[0]], glm::vec3(1, 0, 0));
    EXPECT_EQ(mesh.vertices[second[2]], glm::vec3(0, 1, 0));
    EXPECT_NE(second[0], 1u);
    EXPECT_NE(second[2], 2u);
}

TEST_F(ObjImport, NormalsOfOnlySomeFacesAreNotUsedAndSaySo) {
    write("half.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//1\nf 1 3 2\n");
    const SceneDescription scene = load_file("half.obj");
    EXPECT_TRUE(scene.meshes[0].normals.empty());
    ASSERT_EQ(scene.notes.size(), 1u);
    EXPECT_NE(scene.notes[0].find("no vertex normal"), std::string::npos) << scene.notes[0];
}

TEST_F(ObjImport, MtlMaterialsMapToOursWithFromFile) {
    write("m.mtl", "newmtl red\nKd 0.8 0.1 0.1\nmap_Ks red.png\n"
                   "newmtl glow\nKd 0 0 0\nKe 3 2 1\n"
                   "newmtl chrome\nillum 5\nKs 0.9 0.9 0.9\n"
                   "newmtl glass\nillum 7\nNi 1.33\n");
    write("m.obj", "mtllib m.mtl\n" + kPentagon +
                       "usemtl red\nf 1 2 3\nusemtl glow\nf 1 3 4\nusemtl chrome\nf 1 4 5\nusemtl glass\nf 2 3 4\n"
                       "usemtl red\nf 2 4 5\n");
    const SceneDescription scene = load(R"({"type": "mesh_file", "file": "m.obj", "material": "from_file"})");
    ASSERT_EQ(scene.materials.size(), 6u);  // white, lamp, then the file's four
    EXPECT_EQ(scene.materials[2].name, "m.obj/red");
    EXPECT_EQ(scene.materials[2].type, MaterialType::lambertian);
    EXPECT_EQ(scene.materials[2].albedo, glm::vec3(0.8f, 0.1f, 0.1f));
    EXPECT_EQ(scene.materials[3].name, "m.obj/glow");
    EXPECT_EQ(scene.materials[3].emission, glm::vec3(3, 2, 1));
    EXPECT_EQ(scene.materials[4].type, MaterialType::mirror);
    EXPECT_EQ(scene.materials[4].reflectance, glm::vec3(0.9f));
    EXPECT_EQ(scene.materials[5].type, MaterialType::glass);
    EXPECT_FLOAT_EQ(scene.materials[5].ior, 1.33f);

    // One mesh per material, in order of first use, each with only the vertices it uses.
    ASSERT_EQ(scene.meshes.size(), 4u);
    EXPECT_EQ(scene.meshes[0].material, 2u);
    EXPECT_EQ(scene.meshes[0].triangles, (Triangles{{0, 1, 2}, {1, 3, 4}}));  // vertices 1 2 3 4 5
    EXPECT_EQ(scene.meshes[0].vertices.size(), 5u);
    EXPECT_EQ(scene.meshes[1].material, 3u);
    EXPECT_EQ(scene.meshes[1].vertices, (std::vector<glm::vec3>{{0, 0, 0}, {1.5f, 1, 0}, {0.5f, 2, 0}}));
    EXPECT_EQ(scene.meshes[2].material, 4u);
    EXPECT_EQ(scene.meshes[3].material, 5u);

    // One line names what could not be mapped.
    ASSERT_EQ(scene.notes.size(), 1u);
    EXPECT_NE(scene.notes[0].find("not mapped"), std::string::npos) << scene.notes[0];
    EXPECT_NE(scene.notes[0].find("red: map_Ks texture"), std::string::npos) << scene.notes[0];
}

TEST_F(ObjImport, TheSceneMaterialOverridesTheFileMaterials) {
    write("m.mtl", "newmtl red\nKd 0.8 0.1 0.1\n");
    write("m.obj", "mtllib m.mtl\n" + kPentagon + "usemtl red\nf 1 2 3\n");
    const SceneDescription scene = load_file("m.obj");
    EXPECT_EQ(scene.materials.size(), 2u);
    ASSERT_EQ(scene.meshes.size(), 1u);
    EXPECT_EQ(scene.meshes[0].material, 0u);
    EXPECT_TRUE(scene.notes.empty());
}

TEST_F(ObjImport, FacesWithoutAMaterialGetTheFileDefault) {
    write("m.mtl", "newmtl red\nKd 0.8 0.1 0.1\n");
    write("m.obj", "mtllib m.mtl\n" + kPentagon + "f 1 2 3\nusemtl red\nf 1 3 4\n");
    const SceneDescription scene = load(R"({"type": "mesh_file", "file": "m.obj", "material": "from_file"})");
    ASSERT_EQ(scene.meshes.size(), 2u);
    EXPECT_EQ(scene.materials[scene.meshes[0].material].name, "m.obj/default");
    EXPECT_EQ(scene.materials[scene.meshes[1].material].name, "m.obj/red");
}

TEST_F(ObjImport, WhatDoesNotPlaceAVertexIsSkipped) {
    // w and vertex colours after x y z, a leading "+", texture coordinates in the corners (by
    // a negative index too), trailing comments, tabs, lines, points, smoothing groups.
    write("extras.obj", "v 0 0 0 1\nv\t+1 0 0 0.5 0.5 0.5\nv 0 1 0 # the top\nvt 0 0\nvt 1 0\nvn 0 0 1\n"
                        "s 1\nl 1 2\np 3\nf 1/1 2/-1 3/1 # a comment\nf 1/1/1 3/2/1 2//1\n");
    const TriangleMesh mesh = load_file("extras.obj").meshes[0];
    EXPECT_EQ(mesh.triangles, (Triangles{{0, 1, 2}, {0, 2, 1}}));
    EXPECT_EQ(mesh.vertices, (std::vector<glm::vec3>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}));
}

TEST_F(ObjImport, CarriageReturnsAloneEndLines) {
    write("mac.obj", "v 0 0 0\rv 1 0 0\rv 0 1 0\rf 1 2 3\rf 1 2 4\r");
    // Line 5 is the fifth statement, however the lines end.
    expect_mesh_error(error_for("mac.obj"), "mac.obj", "mac.obj:5: vertex index 4 out of range (the file has 3 vertices)");
    write("mac.obj", "v 0 0 0\rv 1 0 0\r\nv 0 1 0\rf 1 2 3\r");
    EXPECT_EQ(load_file("mac.obj").meshes[0].vertices, (std::vector<glm::vec3>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}));
}

TEST_F(ObjImport, AUtf8ByteOrderMarkIsSkippedAndUtf16IsAnError) {
    write("bom.obj", "\xEF\xBB\xBFv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    EXPECT_EQ(load_file("bom.obj").meshes[0].vertices, (std::vector<glm::vec3>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}));
    write("utf16.obj", std::string("\xFF\xFEv\0 \0", 6));
    expect_mesh_error(error_for("utf16.obj"), "utf16.obj", "utf16.obj:1: the file is UTF-16 text (it starts with a byte order mark)");
}

TEST_F(ObjImport, MaterialNamesAreTrimmedAsInTheMtlFile) {
    // tinyobjloader trims newmtl names but kept usemtl's blanks, so these two did not match.
    write("m.mtl", "newmtl Hard Shiny Plastic \nKd 0.8 0.1 0.1\n");
    write("m.obj", "mtllib m.mtl\n" + kPentagon + "usemtl  Hard Shiny Plastic  \nf 1 2 3\n");
    const SceneDescription scene = load(R"({"type": "mesh_file", "file": "m.obj", "material": "from_file"})");
    ASSERT_EQ(scene.meshes.size(), 1u);
    EXPECT_EQ(scene.materials[scene.meshes[0].material].name, "m.obj/Hard Shiny Plastic");
}

TEST_F(ObjImport, TinyCoordinatesAreKeptAndUnderflowIsZero) {
    // 1e-40 is a float denormal; 1e-400 is below even a double's range.
    write("tiny.obj", "v 1e-40 -1e-400 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    const glm::vec3 v = load_file("tiny.obj").meshes[0].vertices[0];
    EXPECT_EQ(v.x, 1e-40f);
    EXPECT_EQ(v.y, 0.0f);
}

TEST_F(ObjImport, EveryMtllibFileIsRead) {
    write("a.mtl", "newmtl red\nKd 0.8 0.1 0.1\n");
    write("b c.mtl", "newmtl blue\nKd 0.1 0.1 0.8\n");
    write("m.obj", "mtllib a.mtl b\\ c.mtl\n" + kPentagon + "usemtl blue\nf 1 2 3\nusemtl red\nf 1 3 4\n");
    const SceneDescription scene = load(R"({"type": "mesh_file", "file": "m.obj", "material": "from_file"})");
    ASSERT_EQ(scene.meshes.size(), 2u);
    EXPECT_EQ(scene.materials[scene.meshes[0].material].name, "m.obj/blue");
    EXPECT_EQ(scene.materials[scene.meshes[1].material].name, "m.obj/red");
    EXPECT_TRUE(scene.notes.empty()) << scene.notes[0];
}

TEST_F(ObjImport, AMissingMtlFileOrMaterialIsANoteWithItsLine) {
    write("m.obj", kPentagon + "mtllib nope.mtl\nusemtl red\nf 1 2 3\nusemtl red\nf 1 3 4\n");
    const SceneDescription scene = load(R"({"type": "mesh_file", "file": "m.obj", "material": "from_file"})");
    ASSERT_EQ(scene.meshes.size(), 1u);
    EXPECT_EQ(scene.materials[scene.meshes[0].material].name, "m.obj/default");
    ASSERT_EQ(scene.notes.size(), 2u);  // the second "usemtl red" says nothing new
    EXPECT_NE(scene.notes[0].find("m.obj: line 6: mtllib nope.mtl: not read ("), std::string::npos) << scene.notes[0];
    EXPECT_NE(scene.notes[0].find("nope.mtl: cannot open: No such file or directory"), std::string::npos) << scene.notes[0];
    EXPECT_NE(scene.notes[1].find("m.obj: line 7: usemtl red: no such material"), std::string::npos) << scene.notes[1];
}

// ---------------------------------------------------------------------------------------------
// Bad input

TEST_F(ObjImport, IndexOutOfRange) {
    write("bad.obj", kPentagon + "f 1 2 3\nf 1 2 6\n");
    expect_mesh_error(error_for("bad.obj"), "bad.obj", "bad.obj:7: vertex index 6 out of range (the file has 5 vertices)");
}

TEST_F(ObjImport, NegativeIndexBeforeTheFirstVertex) {
    write("bad.obj", kPentagon + "f -1 -2 -6\n");
    expect_mesh_error(error_for("bad.obj"), "bad.obj", "bad.obj:6: vertex index -6 reaches before the first (5 defined so far)");
}

TEST_F(ObjImport, FacesMayNameVerticesDefinedLater) {
    write("later.obj", "v 0 0 0\nf 1 2 3\nv 1 0 0\nv 0 1 0\n");
    EXPECT_EQ(load_file("later.obj").meshes[0].triangles, (Triangles{{0, 1, 2}}));
    write("never.obj", "v 0 0 0\nf 1 2 3\nv 1 0 0\n");
    expect_mesh_error(error_for("never.obj"), "never.obj", "never.obj:2: vertex index 3 out of range (the file has 2 vertices)");
}

TEST_F(ObjImport, NormalIndexOutOfRange) {
    write("bad.obj", kPentagon + "vn 0 0 1\nf 1//1 2//1 3//2\n");
    expect_mesh_error(error_for("bad.obj"), "bad.obj", "bad.obj:7: normal index 2 out of range (1 normals defined so far)");
}

TEST_F(ObjImport, ZeroIndex) {
    write("bad.obj", kPentagon + "\nf 1 2 3\nf 0 1 2\n");
    expect_mesh_error(error_for("bad.obj"), "bad.obj", "bad.obj:8: vertex index 0 (OBJ counts from 1)");
}

TEST_F(ObjImport, FaceWithTwoVertices) {
    write("bad.obj", kPentagon + "f 1 2 3\ng two\nf 1 2\n");
    expect_mesh_error(error_for("bad.obj"), "bad.obj", "bad.obj:8: a face needs at least 3 vertices, got 2");
}

TEST_F(ObjImport, InfiniteVertex) {
    write("bad.obj", "v 0 0 0\nv 1e999 0 0\nv 0 1 0\nf 1 2 3\n");
    expect_mesh_error(error_for("bad.obj"), "bad.obj", "bad.obj:2: vertex coordinate \"1e999\" is not finite");
}

TEST_F(ObjImport, CoordinatesThatAreNotFiniteNumbersNameTheLine) {
    // tinyobjloader read all of these as 0, so the file loaded with vertices at the origin.
    const struct { const char* line; const char* problem; } cases[] = {
        {"v nan 0 0", "bad.obj:2: vertex coordinate \"nan\" is not finite"},
        {"v 0 -inf 0", "bad.obj:2: vertex coordinate \"-inf\" is not finite"},
        {"v 1e39 0 0", "bad.obj:2: vertex coordinate \"1e39\" is not finite in float"},
        {"v abc 0 0", "bad.obj:2: vertex coordinate \"abc\" is not a number"},
        {"v 0 1.5abc 0", "bad.obj:2: vertex coordinate \"1.5abc\" is not a number"},
        {"v 0 0x10 0", "bad.obj:2: vertex coordinate \"0x10\" is not a number"},
        {"v 0 ++1 0", "bad.obj:2: vertex coordinate \"++1\" is not a number"},
        {"v 1 2", "bad.obj:2: a vertex needs 3 coordinates, got 2"},
        {"v 1 2 # 3", "bad.obj:2: a vertex needs 3 coordinates, got 2"},
        {"vn 0 0 x", "bad.obj:2: normal coordinate \"x\" is not a number"},
        {"vn nan 0 1", "bad.obj:2: normal coordinate \"nan\" is not finite"},
    };
    for (const auto& c : cases) {
        write("bad.obj", std::string("v 0 0 0\n") + c.line + "\nv 1 0 0\nv 0 1 0\nf 1 3 4\n");
        expect_mesh_error(error_for("bad.obj"), "bad.obj", c.problem);
    }
}

TEST_F(ObjImport, IndicesAreReportedAsWritten) {
    // Past 2^32 (tinyobjloader wrapped 99999999999 to 1215752191), past 2^63, and not numbers.
    const struct { const char* face; const char* problem; } cases[] = {
        {"f 1 2 99999999999", "bad.obj:6: vertex index 99999999999 out of range (the file has 5 vertices)"},
        {"f 1 2 99999999999999999999999", "bad.obj:6: vertex index 99999999999999999999999 out of range"},
        {"f 1 2 -99999999999", "bad.obj:6: vertex index -99999999999 reaches before the first (5 defined so far)"},
        {"f 1 2 x", "bad.obj:6: vertex index \"x\" is not an integer"},
        {"f 1 2 3.0", "bad.obj:6: vertex index \"3.0\" is not an integer"},
        {"f 1 2/x 3", "bad.obj:6: texture coordinate index \"x\" is not an integer"},
        {"f 1 2//0 3", "bad.obj:6: normal index 0 (OBJ counts from 1)"},
        {"f 1 2/1/ 3", "bad.obj:6: face corner \"2/1/\" is not v, v/vt, v/vt/vn or v//vn"},
        {"f 1 2/1/1/1 3", "bad.obj:6: face corner \"2/1/1/1\" is not v, v/vt, v/vt/vn or v//vn"},
        {"f", "bad.obj:6: a face needs at least 3 vertices, got 0"},
    };
    for (const auto& c : cases) {
        write("bad.obj", kPentagon + c.face + "\n");
        expect_mesh_error(error_for("bad.obj"), "bad.obj", c.problem);
    }
}

TEST_F(ObjImport, NoFacesIsAnEmptyMesh) {
    write("empty.obj", kPentagon);
    expect_mesh_error(error_for("empty.obj"), "empty.obj", "no triangles (an empty mesh)");
}

TEST_F(ObjImport, MissingFile) {
    expect_mesh_error(error_for("nope.obj"), "nope.obj", "cannot open: No such file or directory");
}

TEST_F(ObjImport, UnknownExtension) {
    write("mesh.stl", "solid x\n");
    expect_mesh_error(error_for("mesh.stl"), "mesh.stl", "unknown mesh file extension \".stl\" (allowed: .obj, .ply, .gltf, .glb)");
}

}  // namespace
