// scene_content_hash: what a checkpoint is matched to. Any change to what renders changes it;
// the settings and empty lists do not trouble it.

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
