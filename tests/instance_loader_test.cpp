// The scene file's "meshes" and "instance" shape: what they load into, and every bad input
// refused with the field named.

#include <gtest/gtest.h>

#include "core/scene/scene.h"
#include "core/description/scene_hash.h"
#include "scene_test_helpers.h"

namespace {

// The valid scene with a named mesh ("tri", one triangle) and `instance` added as a shape.
std::string with_instance(const Json& instance, const Json& extra_meshes = Json::object()) {
    return mutated([&](Json& j) {
        j["meshes"] = {{"tri", {{"type", "mesh"}, {"vertices", {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}},
                                {"triangles", {{0, 1, 2}}}, {"material", "white"}}}};
        for (auto it = extra_meshes.begin(); it != extra_meshes.end(); ++it) j["meshes"][it.key()] = it.value();
        j["shapes"].push_back(instance);
    });
}

Json instance_of(const std::string& name, const Json& transforms) {
    return {{"type", "instance"}, {"of", name}, {"transforms", transforms}};
}

TEST(InstanceLoader, PlacesANamedMeshOnceStored) {
    const Json transforms = Json::array({{{"translate", {1, 2, 3}}},
                                         {{"matrix", {{0, -1, 0, 5}, {1, 0, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}}},
                                         {{"scale", -2}, {"rotate", {{"axis", {0, 0, 1}}, {"degrees", 30}}}}});
    const wt::SceneDescription d = parse_scene_json(with_instance(instance_of("tri", transforms)), kSource);
    ASSERT_EQ(d.prototypes.size(), 1u);
    EXPECT_EQ(d.prototypes[0].name, "tri");
    ASSERT_EQ(d.instances.size(), 3u);
    EXPECT_EQ(d.instances[0].transform[3], glm::dvec4(1, 2, 3, 1));
    EXPECT_EQ(d.instances[1].transform[3], glm::dvec4(5, 0, 0, 1));
    EXPECT_EQ(d.meshes.size(), 2u);  // the scene's own quad and mesh; the named mesh is not drawn by itself
    const wt::Scene scene = wt::build_scene(d);
    EXPECT_EQ(scene.instances.meshes.size(), 1u);
    EXPECT_EQ(scene.instances.instances.size(), 3u);
    EXPECT_EQ(scene.instances.triangle_count, 3u);
    EXPECT_EQ(scene.instances.first_id, scene.primitive_count());
}

// A checkpoint of one placement must not resume another: the hash sees the instances.
TEST(InstanceLoader, SceneHashSeesTheInstances) {
    const auto hash_of = [](const Json& transforms) {
        return wt::scene_content_hash(parse_scene_json(with_instance(instance_of("tri", transforms)), kSource));
    };
    const Json one = Json::array({{{"translate", {1, 2, 3}}}});
    EXPECT_EQ(hash_of(one), hash_of(one));
    EXPECT_NE(hash_of(one), hash_of(Json::array({{{"translate", {1, 2, 4}}}})));
    EXPECT_NE(hash_of(one), hash_of(Json::array({{{"translate", {1, 2, 3}}}, {{"translate", {1, 2, 3}}}})));
}

// Nested: a name that is an instance of another composes the transforms into single placements.
TEST(InstanceLoader, NestedInstancesCompose) {
    const Json pair = instance_of("tri", Json::array({{{"translate", {1, 0, 0}}}, {{"translate", {2, 0, 0}}}}));
    const std::string text = with_instance(instance_of("pair", Json::array({{{"translate", {0, 10, 0}}}})), {{"pair", pair}});
    const wt::SceneDescription d = parse_scene_json(text, kSource);
    ASSERT_EQ(d.instances.size(), 2u);
    EXPECT_EQ(d.instances[0].transform[3], glm::dvec4(1, 10, 0, 1));
    EXPECT_EQ(d.instances[1].transform[3], glm::dvec4(2, 10, 0, 1));
    EXPECT_EQ(d.prototypes.size(), 1u);
}

TEST(InstanceLoader, BadInputNamesTheField) {
    expect_scene_error(with_instance(instance_of("tree", Json::array({Json::object()}))),
                       "shapes[3].of: no mesh named \"tree\" in \"meshes\" (defined: \"tri\")");
    expect_scene_error(with_instance(instance_of("tri", Json::array())),
                       "shapes[3].transforms: an instance needs at least one transform");
    expect_scene_error(with_instance(instance_of("tri", Json::array({{{"matrix", {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 0, 0}, {0, 0, 0, 1}}}}}))),
                       "shapes[3].transforms[0].matrix: is singular");
    expect_scene_error(with_instance(instance_of("tri", Json::array({{{"scale", 0}}}))), "shapes[3].transforms[0].scale: must be non-zero");
    expect_scene_error(with_instance(instance_of("tri", Json::array({{{"translate", {1e39, 0, 0}}}}))),
                       "shapes[3].transforms[0].translate");
    // Composed, two placements each fine in float make one that is not.
    expect_scene_error(with_instance(instance_of("big", Json::array({{{"scale", 1e20}}})), {{"big", instance_of("tri", Json::array({{{"scale", 1e20}}}))}}),
                       "shapes[3].transforms[0]: composed with the placements of \"big\", overflows 32-bit float");
    expect_scene_error(with_instance({{"type", "instance"}, {"of", "tri"}}), "shapes[3].transforms: required key is missing");
    expect_scene_error(with_instance({{"type", "instance"}, {"of", "tri"}, {"transforms", Json::array({Json::object()})}, {"count", 3}}),
                       "shapes[3].count");
    // A cycle, directly and through another name.
    expect_scene_error(with_instance(instance_of("a", Json::array({Json::object()})),
                                     {{"a", instance_of("b", Json::array({Json::object()}))},
                                      {"b", instance_of("a", Json::array({Json::object()}))}}),
                       "reference cycle");
    expect_scene_error(with_instance(instance_of("self", Json::array({Json::object()})), {{"self", instance_of("self", Json::array({Json::object()}))}}),
                       "meshes.self.of: mesh \"self\" places itself: a reference cycle");
    // Spheres and lights cannot be instanced.
    expect_scene_error(with_instance(instance_of("ball", Json::array({Json::object()})),
                                     {{"ball", {{"type", "sphere"}, {"center", {0, 0, 0}}, {"radius", 1}, {"material", "white"}}}}),
                       "meshes.ball: a named mesh holds triangles only");
    expect_scene_error(with_instance(instance_of("glow", Json::array({Json::object()})),
                                     {{"glow", {{"type", "mesh"}, {"vertices", {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}},
                                                {"triangles", {{0, 1, 2}}}, {"material", "lamp"}}}}),
                       "meshes.glow.material: an instanced mesh cannot emit");
    expect_scene_error(mutated([](Json& j) { j["meshes"] = Json::array(); }), "meshes: expected an object");
}

// A count that cannot fit is refused while loading, before anything that size is built: nested
// placements multiply past the instances a scene can hold (2^26, what the top level's leaf
// references index), or past the triangles a hit's 32-bit id can name.
Json translations(int count) {
    Json many = Json::array();
    for (int i = 0; i < count; ++i) many.push_back({{"translate", {i, 0, 0}}});
    return many;
}

TEST(InstanceLoader, HugeCountRefusedBeforeBuilding) {
    const std::string text = with_instance(instance_of("c", Json::array({Json::object()})),
                                           {{"b", instance_of("tri", translations(8192))}, {"c", instance_of("b", translations(8193))}});
    expect_scene_error(text, "meshes.c.transforms: 8193 placements of \"b\" (8192 instances each) make 67117056 instances, "
                             "more than the 67108864 a scene can hold");
    Json strip = {{"type", "mesh"}, {"vertices", Json::array()}, {"triangles", Json::array()}, {"material", "white"}};
    for (int i = 0; i < 202; ++i) strip["vertices"].push_back({i, i % 2, 0});
    for (int i = 0; i < 200; ++i) strip["triangles"].push_back({i, i + 1, i + 2});
    const std::string many_triangles = with_instance(
        instance_of("c", Json::array({Json::object()})),
        {{"strip", strip}, {"b", instance_of("strip", translations(4096))}, {"c", instance_of("b", translations(4096))}});
    expect_scene_error(many_triangles, "meshes.c.transforms: 4096 placements of \"b\" (819200 triangles) make more than the "
                                       "2147483647 triangles a hit's 32-bit id can name");
}

}  // namespace
