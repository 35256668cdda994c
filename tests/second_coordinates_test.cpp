// glTF's TEXCOORD_1: a texture whose texCoord (or KHR_texture_transform's texCoord) is 1 reads
// the second set, stored only where a texture reads it; a primitive without it under such a
// texture is an error naming the file, the primitive, the material and the field.

#include <fstream>
#include <sstream>
#include <utility>

#include <gtest/gtest.h>

#include "core/film/image_output.h"
#include "core/scene_file/scene_error.h"
#include "import_gltf_files.h"
#include "lights_test_scenes.h"
#include "render_helpers.h"

namespace wt {
namespace {

using test::GltfFile;
using Json = nlohmann::json;

class SecondCoordinates : public test::ImportTest {
protected:
    // An 8 x 8 PNG, black where x < 4 and white elsewhere, as a file's bytes.
    std::string half_black_png() const {
        std::vector<float> rgb;
        for (int y = 0; y < 8; ++y)
            for (int x = 0; x < 8; ++x)
                for (int c = 0; c < 3; ++c) rgb.push_back(x < 4 ? 0.0f : 1.0f);
        write_image(path("half.png"), 8, 8, rgb);
        std::ifstream in(path("half.png"), std::ios::binary);
        std::stringstream bytes;
        bytes << in.rdbuf();
        return bytes.str();
    }

    // The 8 x 8 square facing +z, TEXCOORD_0 u along +x and (when `second`) TEXCOORD_1 its
    // mirror image, u along -x; material "panel" (principled) with the half-black texture as its
    // baseColorTexture, `info` merged into its texture info.
    Json square(GltfFile& file, bool second, const Json& info) const {
        const int positions = file.positions({{-4, -4, 0}, {4, -4, 0}, {4, 4, 0}, {-4, 4, 0}});
        const auto coordinates = [&](std::vector<float> values) {
            test::Bytes b;
            for (float t : values) b.put(t);
            return file.accessor({{"bufferView", file.view(b.str())}, {"componentType", 5126}, {"count", 4}, {"type", "VEC2"}});
        };
        Json attributes = {{"POSITION", positions}, {"TEXCOORD_0", coordinates({0, 1, 1, 1, 1, 0, 0, 0})}};
        if (second) attributes["TEXCOORD_1"] = coordinates({1, 1, 0, 1, 0, 0, 1, 0});
        file.primitive({{"attributes", attributes}, {"indices", file.indices({0, 1, 2, 0, 2, 3}, 5125)}, {"material", 0}});
        const int png = file.view(half_black_png());
        Json j = file.json("");
        Json texture = {{"index", 0}};
        if (info.is_object()) texture.update(info);
        j["materials"] = {{{"name", "panel"}, {"pbrMetallicRoughness", {{"baseColorTexture", texture}, {"metallicFactor", 0.0}}}}};
        j["textures"] = {{{"source", 0}}};
        j["images"] = {{{"bufferView", png}, {"mimeType", "image/png"}}};
        return j;
    }

    SceneDescription load_glb(const std::string& name, const Json& j, const GltfFile& file) {
        write(name, test::glb(j.dump(), file.bin()));
        return load(R"({"type": "mesh_file", "file": ")" + name + R"(", "material": "from_file"})");
    }
};

// Seen from above, columns 0-1 see the texture's left edge alone and 14-15 its right one
// (texture_render_test says why): the sums of their red, left and right.
std::pair<double, double> edge_columns(SceneDescription d) {
    test::view_from_above(d, 16, 8);
    const Film film = test::render_film(d, Integrator::wavefront).film;
    std::pair<double, double> sums{0.0, 0.0};
    for (int y = 0; y < 16; ++y)
        for (int x : {0, 1, 14, 15}) (x < 2 ? sums.first : sums.second) += film.pixel_mean(uint32_t(y * 16 + x)).x;
    return sums;
}

TEST_F(SecondCoordinates, ATextureOnTexCoord1ReadsTheSecondSet) {
    GltfFile first_file, second_file, transformed_file;
    const SceneDescription first = load_glb("first.glb", square(first_file, true, {}), first_file);
    const SceneDescription second = load_glb("second.glb", square(second_file, true, {{"texCoord", 1}}), second_file);
    // KHR_texture_transform's texCoord overrides the texture info's.
    const SceneDescription transformed = load_glb(
        "transformed.glb", square(transformed_file, true, {{"extensions", {{"KHR_texture_transform", {{"texCoord", 1}}}}}}), transformed_file);
    // Only a texture on set 1 makes the second set stored.
    EXPECT_TRUE(first.meshes[0].second_uvs.empty());
    EXPECT_EQ(second.meshes[0].second_uvs.size(), 4u);
    EXPECT_EQ(second.textures[0].coordinate_set, 1);
    EXPECT_EQ(transformed.textures[0].coordinate_set, 1);
    for (const std::string& note : second.notes) EXPECT_EQ(note.find("TEXCOORD"), std::string::npos) << note;
    // TEXCOORD_0: black on the left, white on the right; the mirrored TEXCOORD_1 the other way.
    const auto [first_left, first_right] = edge_columns(first);
    const auto [second_left, second_right] = edge_columns(second);
    EXPECT_GT(first_right, 4.0 * first_left);
    EXPECT_GT(second_left, 4.0 * second_right);
    EXPECT_EQ(edge_columns(transformed), std::make_pair(second_left, second_right));
    // The table holds the second set only where a texture reads it.
    EXPECT_GT(build_scene(second).texture_coordinates.bytes(), build_scene(first).texture_coordinates.bytes());
}

TEST_F(SecondCoordinates, MissingSecondSetIsAnErrorAndSetTwoANote) {
    GltfFile file;
    const Json j = square(file, false, {{"texCoord", 1}});
    write("missing.glb", test::glb(j.dump(), file.bin()));
    try {
        load(R"({"type": "mesh_file", "file": "missing.glb", "material": "from_file"})");
        ADD_FAILURE() << "no error";
    } catch (const SceneError& e) {
        test::expect_mesh_error(e.what(), "missing.glb", "mesh 0 primitive 0: no TEXCOORD_1, which baseColorTexture of \"panel\" reads");
    }
    GltfFile third_file;
    const SceneDescription third = load_glb("third.glb", square(third_file, true, {{"texCoord", 2}}), third_file);
    bool noted = false;
    for (const std::string& note : third.notes) noted |= note.find("baseColorTexture on TEXCOORD_2") != std::string::npos;
    EXPECT_TRUE(noted);
    EXPECT_TRUE(third.textures.empty());
}

}  // namespace
}  // namespace wt
