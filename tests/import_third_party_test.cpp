// Files written by other programs, from Debian's assimp-testmodels package (Blender, the
// Khronos glTF samples, the glTF asset generator, collada2gltf), where it is installed: every
// test skips without it (`apt-get install assimp-testmodels`, or bench/install-bench-deps.sh).
// The hand-built files of the other import tests cover the same paths without the package.

#include <cstdio>
#include <filesystem>

#include <glm/geometric.hpp>

#include "import_test_files.h"
#include "instance_scenes.h"

namespace {

using wt::SceneDescription;
using wt::TriangleMesh;
using wt::test::expect_mesh_error;

const std::string kModels = "/usr/share/assimp/models/";

class ThirdPartyFiles : public wt::test::ImportTest {
protected:
    void SetUp() override {
        ImportTest::SetUp();
        if (!std::filesystem::exists(kModels + "glTF2"))
            GTEST_SKIP() << kModels << " is missing: install Debian's assimp-testmodels to run these tests";
    }
};

// The sum of the triangles' area vectors (half their cross products): its length is the area of
// a flat mesh only if every triangle faces the same way.
glm::dvec3 vector_area(const SceneDescription& scene) {
    glm::dvec3 sum(0.0);
    for (const TriangleMesh& mesh : wt::test::flattened(scene).meshes)
        for (const auto& t : mesh.triangles) {
            const glm::dvec3 a = mesh.vertices[t[0]], b = mesh.vertices[t[1]], c = mesh.vertices[t[2]];
            sum += 0.5 * glm::cross(b - a, c - a);
        }
    return sum;
}

double total_area(const SceneDescription& scene) {
    double sum = 0.0;
    for (const TriangleMesh& mesh : wt::test::flattened(scene).meshes)
        for (const auto& t : mesh.triangles) {
            const glm::dvec3 a = mesh.vertices[t[0]], b = mesh.vertices[t[1]], c = mesh.vertices[t[2]];
            sum += 0.5 * glm::length(glm::cross(b - a, c - a));
        }
    return sum;
}

// Placed: the scene's own meshes and every instance's (a glTF mesh several nodes use is stored
// once and placed by instances).
std::size_t triangle_count(const SceneDescription& scene) {
    std::size_t n = 0;
    for (const TriangleMesh& mesh : wt::test::flattened(scene).meshes) n += mesh.triangles.size();
    return n;
}

TEST_F(ThirdPartyFiles, WusonPlyFromBlenderLoadsWithANoteForItsCreatedByLine) {
    const SceneDescription scene = load_file(kModels + "PLY/Wuson.ply");
    EXPECT_EQ(triangle_count(scene), 3732u);  // its header's "element face 3732", all triangles
    ASSERT_FALSE(scene.notes.empty());
    EXPECT_NE(scene.notes[0].find("skipped a header line that is not PLY, line 3: \"Created by Blender3D 247"), std::string::npos)
        << scene.notes[0];
}

TEST_F(ThirdPartyFiles, BoxTexturedIsTheSameAsGltfGlbAndDataUri) {
    const SceneDescription gltf = load_file(kModels + "glTF2/BoxTextured-glTF/BoxTextured.gltf");
    ASSERT_EQ(gltf.meshes.size(), 1u);
    EXPECT_EQ(gltf.meshes[0].triangles.size(), 12u);  // a cube
    for (const char* other : {"glTF2/BoxTextured-glTF-Binary/BoxTextured.glb", "glTF2/BoxTextured-glTF-Embedded/BoxTextured.gltf"}) {
        SCOPED_TRACE(other);
        const SceneDescription scene = load_file(kModels + other);
        ASSERT_EQ(scene.meshes.size(), 1u);
        EXPECT_EQ(scene.meshes[0].vertices, gltf.meshes[0].vertices);
        EXPECT_EQ(scene.meshes[0].triangles, gltf.meshes[0].triangles);
        EXPECT_EQ(scene.meshes[0].normals, gltf.meshes[0].normals);
    }
}

TEST_F(ThirdPartyFiles, TwoCylinderEngineLoadsAndItsDracoVersionIsRefused) {
    const SceneDescription engine = load_file(kModels + "glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb");
    EXPECT_GT(triangle_count(engine), 100000u);
    // 29 meshes in 82 nodes: the meshes several nodes use are stored once and placed by instances.
    std::printf("2CylinderEngine: %zu stored meshes, %zu instances, %zu triangles placed\n", engine.prototypes.size(),
                engine.instances.size(), triangle_count(engine));
    EXPECT_FALSE(engine.prototypes.empty());
    EXPECT_GT(engine.instances.size(), engine.prototypes.size());
    const std::string draco = kModels + "glTF2/draco/2CylinderEngine.gltf";
    expect_mesh_error(error_for(draco), draco, "requires extension KHR_draco_mesh_compression (extensionsRequired), which is not supported");
}

TEST_F(ThirdPartyFiles, AssetGeneratorStripsAndFansAreTheSquareItsTrianglesAre) {
    // The generator's README: every model's indices draw the same square; 04/11 as a strip,
    // 05/12 as a fan, 06/13/14/15 as triangles (13-15 indexed by int, byte and short).
    const auto file = [](const char* n) { return kModels + "glTF2/glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_" + n + ".gltf"; };
    const SceneDescription triangles = load_file(file("06"));
    const glm::dvec3 reference = vector_area(triangles);
    ASSERT_GT(glm::length(reference), 0.0);
    EXPECT_NEAR(glm::length(reference), total_area(triangles), 1e-9);
    for (const char* n : {"04", "05", "11", "12", "13", "14", "15"}) {
        SCOPED_TRACE(n);
        const SceneDescription scene = load_file(file(n));
        EXPECT_EQ(triangle_count(scene), 2u);
        const glm::dvec3 area = vector_area(scene);
        // The same area, all of it facing the same way as the triangles' file.
        EXPECT_NEAR(area.x, reference.x, 1e-6);
        EXPECT_NEAR(area.y, reference.y, 1e-6);
        EXPECT_NEAR(area.z, reference.z, 1e-6);
        EXPECT_NEAR(glm::length(area), total_area(scene), 1e-9);
    }
    for (const char* n : {"00", "01", "02", "03", "07", "08", "09", "10"}) {
        SCOPED_TRACE(n);
        expect_mesh_error(error_for(file(n)), file(n), "no triangles: its primitives are points or lines (mesh 0 primitive 0: mode ");
    }
}

TEST_F(ThirdPartyFiles, GltfOneFilesAreRefusedAsSuch) {
    for (const char* name : {"glTF/BoxTextured-glTF/BoxTextured.gltf", "glTF/CesiumMilkTruck/CesiumMilkTruck.gltf",
                             "glTF/TwoBoxes/TwoBoxes.gltf", "glTF/IncorrectVertexArrays/Cube_v1.gltf"}) {
        SCOPED_TRACE(name);
        expect_mesh_error(error_for(kModels + name), name, "glTF 1.0 is not supported (version 2.0 is)");
    }
}

TEST_F(ThirdPartyFiles, ObjFilesLoadOrSayWhichLineIsWrong) {
    for (const char* name : {"OBJ/WusonOBJ.obj", "OBJ/spider.obj", "OBJ/box_mat_with_spaces.obj", "OBJ/cube_with_vertexcolors.obj"}) {
        SCOPED_TRACE(name);
        EXPECT_GT(triangle_count(load_file(kModels + name)), 0u);
    }
    // assimp's own number-format test: "3.1+e2" is not a number (tinyobjloader read 3.1).
    expect_mesh_error(error_for(kModels + "OBJ/number_formats.obj"), "number_formats.obj",
                      "number_formats.obj:11: vertex coordinate \"3.1+e2\" is not a number");
}

}  // namespace
