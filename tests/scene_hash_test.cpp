// scene_content_hash: what a checkpoint is matched to. Any change to what renders changes it;
// the settings and empty lists do not trouble it.

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "core/description/scene_hash.h"
#include "test_scenes.h"

namespace wt {
namespace {

TEST(SceneHash, TheSameSceneHashesTheSameAndAnyRenderedChangeDiffers) {
    const SceneDescription base = test::hexroom(8, 8, 4);
    EXPECT_EQ(scene_content_hash(base), scene_content_hash(test::hexroom(8, 8, 4)));
    SceneDescription settings = base;
    settings.settings.seed = 99, settings.settings.spp = 7;
    EXPECT_EQ(scene_content_hash(base), scene_content_hash(settings)) << "settings are compared one by one, not hashed";

    SceneDescription vertex = base;
    vertex.meshes[0].vertices[0].x = std::nextafter(vertex.meshes[0].vertices[0].x, 1e9f);
    SceneDescription albedo = base;
    albedo.materials[0].albedo.y += 0.01f;
    SceneDescription camera = base;
    camera.camera.fov_degrees += 1.0f;
    for (const SceneDescription* changed : {&vertex, &albedo, &camera})
        EXPECT_NE(scene_content_hash(base), scene_content_hash(*changed));
}

// Each per-vertex attribute a hit reads (positions, normals, both coordinate sets, tangents), in
// a mesh of the scene and in a part of an instanced prototype alike: changing one number of it
// changes the hash, so a checkpoint is never resumed on another mesh's coordinates.
TEST(SceneHash, EveryVertexAttributeOfMeshesAndPrototypesCounts) {
    SceneDescription base = test::hexroom(8, 8, 4);
    TriangleMesh part;
    part.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    part.triangles = {{0, 1, 2}};
    part.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
    part.uvs = {{0, 0}, {1, 0}, {0, 1}};
    part.second_uvs = {{0, 0}, {0, 1}, {1, 0}};
    part.tangents = {{1, 0, 0, 1}, {1, 0, 0, 1}, {1, 0, 0, 1}};
    base.meshes.push_back(part);
    base.prototypes.push_back({"card", {part}});
    base.instances.push_back({0, glm::dmat4(1.0)});
    const uint64_t hash = scene_content_hash(base);
    EXPECT_EQ(hash, scene_content_hash(SceneDescription(base)));

    const std::vector<std::pair<std::string, void (*)(TriangleMesh&)>> changes = {
        {"vertices", [](TriangleMesh& m) { m.vertices[2].y = std::nextafter(m.vertices[2].y, 1e9f); }},
        {"normals", [](TriangleMesh& m) { m.normals[2].y = std::nextafter(m.normals[2].y, 1e9f); }},
        {"uvs", [](TriangleMesh& m) { m.uvs[2].y = std::nextafter(m.uvs[2].y, 1e9f); }},
        {"second_uvs", [](TriangleMesh& m) { m.second_uvs[2].y = std::nextafter(m.second_uvs[2].y, 1e9f); }},
        {"tangents", [](TriangleMesh& m) { m.tangents[2].y = std::nextafter(m.tangents[2].y, 1e9f); }},
    };
    for (const auto& [name, change] : changes) {
        SceneDescription mesh = base, prototype = base;
        change(mesh.meshes.back());
        change(prototype.prototypes[0].parts[0]);
        EXPECT_NE(scene_content_hash(mesh), hash) << "a mesh's " << name;
        EXPECT_NE(scene_content_hash(prototype), hash) << "a prototype part's " << name;
    }
}

TEST(SceneHash, EmptyListsHash) {
    // Empty vectors (data() may be null) and a scene of nothing: a hash, not undefined behaviour.
    SceneDescription empty;
    SceneDescription one_sphere;
    one_sphere.spheres.push_back({});
    EXPECT_NE(scene_content_hash(empty), scene_content_hash(one_sphere));
    EXPECT_EQ(hash_to_hex(0x0123456789abcdefull), "0123456789abcdef");
}

}  // namespace
}  // namespace wt
