// Textures from glTF files: an image inside a .glb, in a data URI and in an external PNG, each
// read through the image module (the test writes its PNGs with it); a .glb's half-black,
// half-white texture renders each half as the untextured black and white materials do, bit for
// bit; and bad images (missing, corrupt, too large) are errors naming the file, the material
// and the field, while a non-power-of-two image is a texture like any other. An emissiveTexture
// (and a scene file's emission texture) emits from the white half alone.

#include <fstream>
#include <sstream>
#include <stdexcept>

#include <gtest/gtest.h>

#include "core/film/image_output.h"
#include "core/scene_file/scene_error.h"
#include "core/textures/texture_file.h"
#include "import_gltf_files.h"
#include "lights_test_scenes.h"
#include "render_helpers.h"
#include "test_image_files.h"

namespace wt {
namespace {

using test::GltfFile;
using Json = nlohmann::json;

class TextureImport : public test::ImportTest {
protected:
    // A PNG of width x height, black where x < width / 2 and white elsewhere, as a file's bytes.
    std::string half_black_png(int width, int height, const std::string& name = "texture.png") const {
        std::vector<float> rgb;
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x)
                for (int c = 0; c < 3; ++c) rgb.push_back(x < width / 2 ? 0.0f : 1.0f);
        std::filesystem::create_directories(std::filesystem::path(path(name)).parent_path());
        write_image(path(name), width, height, rgb);
        std::ifstream in(path(name), std::ios::binary);
        std::stringstream bytes;
        bytes << in.rdbuf();
        return bytes.str();
    }

    // A square of side 8 in the z = 0 plane facing +z, TEXCOORD_0 over [0, 1]^2 (v = 0 at
    // y = +4), its material principled (metallic 0, roughness 0.5) with baseColorTexture 0 whose
    // image is `image` (a bufferView's PNG bytes when `png` is given). Returns the file's JSON
    // and fills `file`'s buffer.
    static Json square(GltfFile& file, const Json& image, const std::string& png = "") {
        const int positions = file.positions({{-4, -4, 0}, {4, -4, 0}, {4, 4, 0}, {-4, 4, 0}});
        test::Bytes uv;
        for (float t : {0.0f, 1.0f, 1.0f, 1.0f, 1.0f, 0.0f, 0.0f, 0.0f}) uv.put(t);
        const int uvs = file.accessor({{"bufferView", file.view(uv.str())}, {"componentType", 5126}, {"count", 4}, {"type", "VEC2"}});
        const int indices = file.indices({0, 1, 2, 0, 2, 3}, 5125);
        file.primitive({{"attributes", {{"POSITION", positions}, {"TEXCOORD_0", uvs}}}, {"indices", indices}, {"material", 0}});
        Json img = image;
        if (!png.empty()) img = {{"bufferView", file.view(png)}, {"mimeType", "image/png"}};
        Json j = file.json("");
        j["materials"] = {{{"name", "panel"},
                           {"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}, {"metallicFactor", 0.0}, {"roughnessFactor", 0.5}}}}};
        j["textures"] = {{{"source", 0}, {"sampler", 0}}};
        j["samplers"] = {{{"wrapS", 33071}, {"wrapT", 33648}}};  // CLAMP_TO_EDGE, MIRRORED_REPEAT
        j["images"] = {img};
        return j;
    }

    std::string gltf_text(const GltfFile& file, Json j) const {
        j["buffers"][0]["uri"] = "data:application/octet-stream;base64," + test::base64(file.bin());
        return j.dump();
    }

    SceneDescription load_from_file(const std::string& name) const {
        return load(R"({"type": "mesh_file", "file": ")" + name + R"(", "material": "from_file"})");
    }

    std::string texture_error(const std::string& name) const {
        try {
            load_from_file(name);
        } catch (const SceneError& e) {
            return e.what();
        }
        ADD_FAILURE() << "no SceneError for " << name;
        return "";
    }
};

// Seen from above, the pixels that see one half of a half-black, half-white texture alone
// (columns 0-1 and 14-15, texture_render_test says why) have exactly the bits of the same scene
// rendered untextured in that colour; and the image is the same for every schedule.
// Seen from above with no other light, a square emitting through the half-black texture: its
// left columns 0 exactly, its right ones `white` within float rounding.
void expect_emitted_halves(SceneDescription d, double white) {
    test::view_from_above(d, 16, 4);
    d.lights.clear();
    const Film film = test::render_film(d, Integrator::wavefront).film;
    for (int y = 0; y < 16; ++y) {
        for (int x : {0, 1}) EXPECT_EQ(film.pixel_mean(uint32_t(y * 16 + x)).x, 0.0) << x << "," << y;
        for (int x : {14, 15}) EXPECT_NEAR(film.pixel_mean(uint32_t(y * 16 + x)).x, white, 1e-6 * white) << x << "," << y;
    }
}

void expect_halves_render_as_their_colours(SceneDescription d) {
    test::view_from_above(d, 16, 8);
    const Film film = test::render_film(d, Integrator::wavefront).film;
    for (float colour : {0.0f, 1.0f}) {
        SceneDescription plain = d;
        plain.textures.clear();
        for (Material& m : plain.materials) {
            if (m.color_texture < 0) continue;
            m.color_texture = -1;
            (m.type == MaterialType::principled ? m.base_color : m.albedo) *= colour;
        }
        const Film expected = test::render_film(plain, Integrator::wavefront).film;
        for (int y = 0; y < 16; ++y)
            for (int x : colour == 0.0f ? std::vector<int>{0, 1} : std::vector<int>{14, 15}) {
                const uint32_t p = uint32_t(y * 16 + x);
                EXPECT_EQ(film.pixel_mean(p), expected.pixel_mean(p)) << x << "," << y << " colour " << colour;
            }
    }
    test::expect_same_film_for_any_schedule(d, film);
}

TEST_F(TextureImport, GlbImageRendersEachHalfAsItsColour) {
    GltfFile file;
    const Json j = square(file, {}, half_black_png(8, 8));
    write("panel.glb", test::glb(j.dump(), file.bin()));
    SceneDescription d = load_from_file("panel.glb");
    ASSERT_EQ(d.textures.size(), 1u);
    const TextureImage& t = d.textures[0];
    EXPECT_TRUE(t.srgb);
    EXPECT_EQ(t.wrap_s, TextureWrap::clamp);
    EXPECT_EQ(t.wrap_t, TextureWrap::mirror);
    ASSERT_EQ(t.texels->width, 8);
    EXPECT_EQ(t.texels->rgba[0], glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
    EXPECT_EQ(t.texels->rgba[7], glm::vec4(1.0f));
    EXPECT_NE(t.name.find("baseColorTexture"), std::string::npos) << t.name;
    // No note says the texture is not mapped.
    for (const std::string& note : d.notes) EXPECT_EQ(note.find("baseColorTexture"), std::string::npos) << note;

    expect_halves_render_as_their_colours(d);
}

TEST_F(TextureImport, MetallicRoughnessTextureAndTextureTransform) {
    GltfFile file;
    Json j = square(file, {}, half_black_png(4, 4));
    j["textures"].push_back({{"source", 0}});
    Json& pbr = j["materials"][0]["pbrMetallicRoughness"];
    pbr["metallicFactor"] = 1.0;  // would load as a conductor without the texture
    pbr["metallicRoughnessTexture"] = {{"index", 1}};
    j["materials"][0]["normalTexture"] = {{"index", 1}, {"scale", 0.5}};
    pbr["baseColorTexture"]["extensions"] = {
        {"KHR_texture_transform", {{"offset", {0.25, 0.5}}, {"rotation", 0.5}, {"scale", {2.0, 3.0}}}}};
    write("panel.glb", test::glb(j.dump(), file.bin()));
    const SceneDescription d = load_from_file("panel.glb");
    ASSERT_EQ(d.textures.size(), 3u);
    const Material* panel = nullptr;
    for (const Material& m : d.materials)
        if (m.name.find("panel") != std::string::npos) panel = &m;
    ASSERT_NE(panel, nullptr);
    EXPECT_EQ(panel->type, MaterialType::principled);
    EXPECT_EQ(panel->metallic, 1.0f);
    ASSERT_GE(panel->color_texture, 0);
    ASSERT_GE(panel->metallic_roughness_texture, 0);
    const TextureImage& colour = d.textures[std::size_t(panel->color_texture)];
    const TextureImage& data = d.textures[std::size_t(panel->metallic_roughness_texture)];
    EXPECT_TRUE(colour.srgb);
    EXPECT_FALSE(data.srgb);  // metallic and roughness are data
    EXPECT_EQ(colour.texels, data.texels);  // one image, decoded once
    EXPECT_EQ(colour.offset, glm::vec2(0.25f, 0.5f));
    EXPECT_EQ(colour.scale, glm::vec2(2.0f, 3.0f));
    EXPECT_EQ(colour.rotation, 0.5f);
    EXPECT_EQ(data.scale, glm::vec2(1.0f));
    ASSERT_GE(panel->normal_texture, 0);  // a normal map: data, with its scale
    EXPECT_FALSE(d.textures[std::size_t(panel->normal_texture)].srgb);
    EXPECT_EQ(panel->normal_scale, 0.5f);
    for (const std::string& note : d.notes) {
        EXPECT_EQ(note.find("metallicRoughnessTexture"), std::string::npos) << note;
        EXPECT_EQ(note.find("KHR_texture_transform"), std::string::npos) << note;
        EXPECT_EQ(note.find("normalTexture"), std::string::npos) << note;
    }
    // A transform whose values are not numbers names them.
    pbr["baseColorTexture"]["extensions"]["KHR_texture_transform"]["scale"] = {"big", 1};
    write("bad.glb", test::glb(j.dump(), file.bin()));
    test::expect_mesh_error(texture_error("bad.glb"), "bad.glb", "baseColorTexture: KHR_texture_transform.scale is not a finite number");
}

TEST_F(TextureImport, DataUriAndExternalImagesAndNonPowerOfTwo) {
    const std::string png = half_black_png(6, 3, "odd.png");  // 6 x 3: not a power of two
    for (const Json& image : {Json{{"uri", "data:image/png;base64," + test::base64(png)}}, Json{{"uri", "odd.png"}}}) {
        GltfFile file;
        write("panel.gltf", gltf_text(file, square(file, image)));
        const SceneDescription d = load_from_file("panel.gltf");
        ASSERT_EQ(d.textures.size(), 1u);
        EXPECT_EQ(d.textures[0].texels->width, 6);
        EXPECT_EQ(d.textures[0].texels->height, 3);
        EXPECT_EQ(d.textures[0].texels->rgba[5], glm::vec4(1.0f));
        const Scene scene = build_scene(d);
        ASSERT_EQ(scene.textures.size(), 1u);
        EXPECT_EQ(scene.textures[0].level_count(), 3u);  // 6x3, 3x1, 1x1
        // Its memory: three levels of RGBA floats.
        EXPECT_GE(scene.textures[0].bytes(), (18u + 3u + 1u) * sizeof(glm::vec4));
    }
}

TEST_F(TextureImport, BadImagesNameTheFileMaterialAndField) {
    const auto expect_error = [&](const Json& image, const std::string& png, const std::string& problem) {
        GltfFile file;
        const Json j = square(file, image, png);
        write("panel.glb", test::glb(j.dump(), file.bin()));
        const std::string message = texture_error("panel.glb");
        test::expect_mesh_error(message, "panel.glb", problem);
        EXPECT_NE(message.find("material \"panel\": baseColorTexture"), std::string::npos) << message;
    };
    expect_error({{"uri", "missing.png"}}, "", "image 0 (missing.png): the file is missing or unreadable");
    expect_error({}, "this is not an image at all", "not a PNG or JPEG image");
    std::string truncated = half_black_png(8, 8);
    truncated.resize(truncated.size() / 2);
    expect_error({}, truncated, "image 0");
    // 16385 pixels wide: refused from the header, whatever the file's size.
    expect_error({}, half_black_png(16385, 1), "16385 x 1 pixels, more than the 16384 per side");
    // A PNG cut short in its first pixel data, claiming 2048 x 2048 pixels in a few hundred
    // bytes: refused by its size before 50 MB of pixels are allocated. Whole, the same image reads.
    const std::string big = half_black_png(2048, 2048);
    EXPECT_GT(big.size(), 2048u * 257u / 1032u);
    const std::size_t cut = big.find("IDAT") + 16;
    ASSERT_LT(cut, 510u);
    expect_error({}, big.substr(0, cut),
                 std::to_string(cut) + " bytes cannot hold 2048 x 2048 PNG pixels (at least 510): the file is truncated or damaged");
    GltfFile file;
    const Json whole = square(file, {}, big);
    write("whole.glb", test::glb(whole.dump(), file.bin()));
    EXPECT_EQ(load_from_file("whole.glb").textures.size(), 1u);
}

// An image's bufferView that runs past its buffer is refused naming the image, the view and the
// buffer (tinygltf 2.7 hands the view's bytes over unchecked: fuzz_gltf read past the buffer's heap
// block), by one byte as by 2^32; one that ends exactly at the buffer's end loads.
TEST_F(TextureImport, ImageBufferViewPastItsBufferIsRefused) {
    GltfFile file;
    Json j = square(file, {}, half_black_png(8, 8));
    const std::size_t view = j["images"][0]["bufferView"].get<std::size_t>();
    const std::size_t offset = j["bufferViews"][view]["byteOffset"].get<std::size_t>();
    const std::size_t length = j["bufferViews"][view]["byteLength"].get<std::size_t>();
    ASSERT_EQ(offset + length, file.bin().size()) << "the image is the buffer's last view";
    write("exact.glb", test::glb(j.dump(), file.bin()));
    EXPECT_EQ(load_from_file("exact.glb").textures.size(), 1u);

    const auto expect_refused = [&](std::size_t new_offset, std::size_t new_length) {
        Json bad = j;
        bad["bufferViews"][view]["byteOffset"] = new_offset;
        bad["bufferViews"][view]["byteLength"] = new_length;
        write("past.glb", test::glb(bad.dump(), file.bin()));
        test::expect_mesh_error(texture_error("past.glb"), "past.glb",
                                "image 0: bufferView " + std::to_string(view) + " (bytes " + std::to_string(new_offset) + " to " +
                                    std::to_string(new_offset + new_length) + ") runs past the end of buffer 0 (" +
                                    std::to_string(file.bin().size()) + " bytes)");
    };
    expect_refused(offset, length + 1);
    expect_refused(offset + 4, length);
    expect_refused(offset, length + (std::size_t(1) << 32));
}

// glTF's emissiveTexture (3.9.5) multiplies emissiveFactor and KHR_materials_emissive_strength:
// the half-black, half-white image emits from its white half alone, exactly the factor there.
// An image that cannot be read is an error naming the field; on glass (which cannot emit) and with
// the factor 0 (where it changes nothing) it is not mapped, the first with a note.
TEST_F(TextureImport, GltfEmissiveTextureMultipliesTheFactor) {
    const auto with_emission = [](Json j, bool base_colour) {
        Json& m = j["materials"][0];
        m["emissiveFactor"] = {2.0, 2.0, 2.0};
        m["emissiveTexture"] = {{"index", 0}};
        m["extensions"]["KHR_materials_emissive_strength"] = {{"emissiveStrength", 3.0}};
        if (!base_colour) m["pbrMetallicRoughness"].erase("baseColorTexture");
        return j;
    };
    GltfFile file;
    const Json j = with_emission(square(file, {}, half_black_png(8, 8)), true);
    write("panel.glb", test::glb(j.dump(), file.bin()));
    SceneDescription d = load_from_file("panel.glb");
    const Material& m = d.materials.back();  // after the scene file's own
    EXPECT_EQ(m.name, "panel.glb/panel");
    EXPECT_EQ(m.emission, glm::vec3(6.0f));
    ASSERT_GE(m.emission_texture, 0);
    ASSERT_LT(std::size_t(m.emission_texture), d.textures.size());
    EXPECT_TRUE(d.textures[std::size_t(m.emission_texture)].srgb);
    EXPECT_NE(d.textures[std::size_t(m.emission_texture)].name.find("emissiveTexture"), std::string::npos);
    for (const std::string& note : d.notes) EXPECT_EQ(note.find("emissiveTexture"), std::string::npos) << note;
    // Seen from above with no other light: 0 over the black half, 6 over the white half.
    expect_emitted_halves(d, 6.0);

    // A mesh two nodes share, emitting: placed flattened, once per node, each copy with its
    // coordinates, so the light samples of either copy read black on its left half (u < 0.4375:
    // texels 0 to 3 alone) and the factor on its right half.
    Json shared = j;
    shared["nodes"] = {{{"mesh", 0}, {"translation", {-5.0, 0.0, 0.0}}}, {{"mesh", 0}, {"translation", {5.0, 0.0, 0.0}}}};
    shared["scenes"] = {{{"nodes", {0, 1}}}};
    write("shared.glb", test::glb(shared.dump(), file.bin()));
    const SceneDescription two = load_from_file("shared.glb");
    EXPECT_TRUE(two.prototypes.empty());
    ASSERT_EQ(two.meshes.size(), 2u);
    for (const TriangleMesh& mesh : two.meshes) EXPECT_EQ(mesh.uvs.size(), mesh.vertices.size());
    const Scene lit = build_scene(two);
    ASSERT_EQ(lit.lights.size(), 4u);
    int black = 0, white = 0;
    for (std::size_t k = 0; k < lit.lights.size(); ++k)
        for (int i = 0; i < 64; ++i) {
            const LightSample sample = lit.lights.sample_emitter(k, (float(i % 8) + 0.5f) / 8.0f, (float(i / 8) + 0.5f) / 8.0f);
            const float local_x = sample.position.x - (sample.position.x < 0.0f ? -5.0f : 5.0f);
            if (local_x < -0.6f) {
                EXPECT_EQ(sample.radiance, glm::vec3(0.0f)) << k << " at x " << sample.position.x;
                ++black;
            }
            if (local_x > 0.6f) {
                EXPECT_EQ(sample.radiance, glm::vec3(6.0f)) << k << " at x " << sample.position.x;
                ++white;
            }
        }
    EXPECT_GT(black, 32);
    EXPECT_GT(white, 32);

    GltfFile missing_file;
    const Json missing = with_emission(square(missing_file, {{"uri", "missing.png"}}), false);
    write("missing.glb", test::glb(missing.dump(), missing_file.bin()));
    const std::string message = texture_error("missing.glb");
    test::expect_mesh_error(message, "missing.glb", "material \"panel\": emissiveTexture: image 0 (missing.png): the file is missing or unreadable");

    GltfFile glass_file;
    Json glass = with_emission(square(glass_file, {}, half_black_png(8, 8)), false);
    glass["materials"][0]["extensions"]["KHR_materials_transmission"] = {{"transmissionFactor", 1.0}};
    write("glass.glb", test::glb(glass.dump(), glass_file.bin()));
    const SceneDescription g = load_from_file("glass.glb");
    EXPECT_EQ(g.materials.back().emission_texture, -1);
    ASSERT_EQ(g.notes.size(), 1u);
    EXPECT_NE(g.notes[0].find("emissiveTexture"), std::string::npos) << g.notes[0];

    GltfFile dark_file;
    Json dark = with_emission(square(dark_file, {}, half_black_png(8, 8)), false);
    dark["materials"][0]["emissiveFactor"] = {0.0, 0.0, 0.0};
    write("dark.glb", test::glb(dark.dump(), dark_file.bin()));
    const SceneDescription k = load_from_file("dark.glb");
    EXPECT_EQ(k.materials.back().emission_texture, -1);
    EXPECT_FALSE(k.materials.back().is_emissive());
    for (const std::string& note : k.notes) EXPECT_EQ(note.find("emissiveTexture"), std::string::npos) << note;
}

// A scene file's "emission" takes a texture as "albedo" does, its factor allowed above 1.
TEST_F(TextureImport, SceneFileEmissionTexture) {
    half_black_png(8, 8);
    const std::string quad = R"({"type": "quad", "vertices": [[-4, -4, 0], [4, -4, 0], [4, 4, 0], [-4, 4, 0]], "material": "panel"})";
    SceneDescription d = load(quad, R"({"panel": {"type": "lambertian", "albedo": [0, 0, 0],
        "emission": {"texture": "texture.png", "factor": [5, 5, 5]}}})");
    ASSERT_EQ(d.textures.size(), 1u);
    EXPECT_EQ(d.materials[0].emission, glm::vec3(5.0f));
    EXPECT_EQ(d.materials[0].emission_texture, 0);
    EXPECT_EQ(d.meshes[0].uvs.size(), 4u);
    expect_emitted_halves(d, 5.0);
    const SceneDescription p = load(quad, R"({"panel": {"type": "principled", "metallic": 1, "roughness": 0.5,
        "base_color": [1, 1, 1], "emission": {"texture": "texture.png"}}})");
    EXPECT_EQ(p.materials[0].type, MaterialType::principled);  // it emits: not the conductor
    EXPECT_EQ(p.materials[0].emission, glm::vec3(1.0f));
    EXPECT_EQ(p.materials[0].emission_texture, 0);
    try {
        load(quad, R"({"panel": {"type": "lambertian", "albedo": [0, 0, 0], "emission": {"texture": "glow.png"}}})");
        ADD_FAILURE() << "no error for a missing emission texture";
    } catch (const SceneError& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("materials.panel.emission.texture"), std::string::npos) << message;
        EXPECT_NE(message.find("glow.png"), std::string::npos) << message;
    }
}

// A square like square()'s in OBJ: vt with v up (flipped on reading), its material's map_Kd.
TEST_F(TextureImport, ObjMapKdAndTextureCoordinates) {
    half_black_png(8, 8, "maps/texture.png");
    write("panel.mtl", "newmtl panel\nKd 1 1 1\nmap_Kd maps/texture.png\n");
    write("panel.obj", "mtllib panel.mtl\nv -4 -4 0\nv 4 -4 0\nv 4 4 0\nv -4 4 0\n"
                       "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nusemtl panel\nf 1/1 2/2 3/3 4/4\n");
    const SceneDescription d = load_from_file("panel.obj");
    ASSERT_EQ(d.textures.size(), 1u);
    ASSERT_EQ(d.meshes.size(), 1u);
    ASSERT_EQ(d.meshes[0].uvs.size(), 4u);
    EXPECT_EQ(d.meshes[0].uvs[0], glm::vec2(0.0f, 1.0f));  // vt 0 0: the image's bottom-left corner
    EXPECT_EQ(d.meshes[0].uvs[2], glm::vec2(1.0f, 0.0f));
    for (const std::string& note : d.notes) EXPECT_EQ(note.find("map_Kd"), std::string::npos) << note;
    expect_halves_render_as_their_colours(d);

    // A corner with another coordinate splits its vertex: two faces sharing vertex 1 with vt 1 and 2.
    write("split.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nvt 0 0\nvt 1 1\nf 1/1 2/1 3/1\nf 1/2 2/2 4/2\n");
    write("split.mtl", "");
    const SceneDescription split = load(R"({"type": "mesh_file", "file": "split.obj", "material": "textured"})",
                                        R"({"textured": {"type": "lambertian", "albedo": {"texture": "maps/texture.png"}}})");
    ASSERT_EQ(split.meshes.size(), 1u);
    EXPECT_EQ(split.meshes[0].vertices.size(), 6u);  // 4 positions, 2 of them with a second coordinate
    EXPECT_EQ(split.meshes[0].uvs.size(), 6u);

    write("broken.mtl", "newmtl panel\nKd 1 1 1\nmap_Kd nowhere.png\n");
    write("broken.obj", "mtllib broken.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nusemtl panel\nf 1/1 2/1 3/1\n");
    const std::string message = texture_error("broken.obj");
    test::expect_mesh_error(message, "broken.obj", "material \"panel\": map_Kd: ");
    EXPECT_NE(message.find("nowhere.png"), std::string::npos) << message;
}

TEST_F(TextureImport, ObjPbrMapsMakeTheMetallicRoughnessLayout) {
    // map_Pr and map_Pm (grey images, read by their value) become one texture laid out as glTF's:
    // roughness green, metallic blue; each map replaces its value (factor 1, so Pm 0.3 is not
    // read) and keeps the material principled; a missing map's channel is 1; maps of different
    // sizes are an error naming both files; a mirror's map_Pr is a note.
    write("rough.pgm", test::pgm(4, 2, [](int x) { return uint8_t(85 * x); }));
    write("metal.pgm", test::pgm(4, 2, [](int x) { return uint8_t(255 - 85 * x); }));
    write("small.pgm", test::pgm(2, 2, [](int) { return uint8_t(255); }));
    write("m.mtl", "newmtl both\nKd 1 1 1\nPm 0.3\nmap_Pr rough.pgm\nmap_Pm metal.pgm\n"
                   "newmtl rough_metal\nKd 1 1 1\nPm 1\nmap_Pr rough.pgm\n"
                   "newmtl shiny\nillum 3\nKs 1 1 1\nmap_Pr rough.pgm\n");
    write("m.obj", "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nusemtl both\nf 1/1 2/1 3/1\n"
                   "usemtl rough_metal\nf 1/1 3/1 2/1\nusemtl shiny\nf 2/1 1/1 3/1\n");
    const SceneDescription d = load_from_file("m.obj");
    const auto named = [&](const std::string& suffix) -> const Material& {
        for (const Material& m : d.materials)
            if (m.name.size() >= suffix.size() && m.name.compare(m.name.size() - suffix.size(), suffix.size(), suffix) == 0) return m;
        throw std::runtime_error("test bug: no material " + suffix);
    };
    const auto layout = [&](const Material& m) {
        std::vector<glm::vec4> row;
        if (m.metallic_roughness_texture < 0) return row;
        const TextureImage& t = d.textures[std::size_t(m.metallic_roughness_texture)];
        EXPECT_FALSE(t.srgb) << m.name;
        for (int x = 0; x < 4; ++x) row.push_back(t.texels->rgba[std::size_t(x)]);
        return row;
    };
    const Material& both = named("both");
    EXPECT_EQ(both.type, MaterialType::principled);
    EXPECT_EQ(both.metallic, 1.0f);
    EXPECT_EQ(both.roughness, 1.0f);
    const std::vector<glm::vec4> both_row = layout(both);
    ASSERT_EQ(both_row.size(), 4u);
    for (int x = 0; x < 4; ++x) {
        EXPECT_NEAR(both_row[std::size_t(x)].y, 85 * x / 255.0f, 1e-6f) << x;
        EXPECT_NEAR(both_row[std::size_t(x)].z, (255 - 85 * x) / 255.0f, 1e-6f) << x;
    }
    const Material& rough_metal = named("rough_metal");
    EXPECT_EQ(rough_metal.type, MaterialType::principled);  // Pm 1 alone would be a conductor
    EXPECT_EQ(rough_metal.metallic, 1.0f);
    const std::vector<glm::vec4> rough_row = layout(rough_metal);
    ASSERT_EQ(rough_row.size(), 4u);
    for (int x = 0; x < 4; ++x) {
        EXPECT_NEAR(rough_row[std::size_t(x)].y, 85 * x / 255.0f, 1e-6f) << x;
        EXPECT_EQ(rough_row[std::size_t(x)].z, 1.0f) << x;
    }
    EXPECT_EQ(named("shiny").type, MaterialType::mirror);
    EXPECT_EQ(named("shiny").metallic_roughness_texture, -1);
    bool shiny_note = false;
    for (const std::string& note : d.notes) {
        EXPECT_EQ(note.find("both:"), std::string::npos) << note;
        EXPECT_EQ(note.find("rough_metal:"), std::string::npos) << note;
        shiny_note = shiny_note || (note.find("shiny") != std::string::npos && note.find("map_Pr texture") != std::string::npos);
    }
    EXPECT_TRUE(shiny_note);

    write("odd.mtl", "newmtl odd\nKd 1 1 1\nmap_Pr rough.pgm\nmap_Pm small.pgm\n");
    write("odd.obj", "mtllib odd.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nusemtl odd\nf 1/1 2/1 3/1\n");
    const std::string message = texture_error("odd.obj");
    test::expect_mesh_error(message, "odd.obj", "material \"odd\": map_Pr and map_Pm: ");
    for (const char* part : {"rough.pgm (4 x 2)", "small.pgm (2 x 2)", "differ in size"})
        EXPECT_NE(message.find(part), std::string::npos) << part << " not in: " << message;
}

TEST_F(TextureImport, ObjMapKeIsTheEmission) {
    // map_Ke replaces Ke (0 here), as Blender's importer links it into the emission colour: the
    // screen emits the texture's colour (an sRGB colour texture, factor 1); a mirror cannot emit,
    // so its map_Ke is a note, not a texture.
    half_black_png(8, 8, "screen.png");
    write("m.mtl", "newmtl screen\nKd 0 0 0\nKe 0 0 0\nmap_Ke screen.png\nnewmtl shiny\nillum 3\nKs 1 1 1\nmap_Ke screen.png\n");
    write("m.obj", "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nusemtl screen\nf 1/1 2/1 3/1\nusemtl shiny\nf 1/1 3/1 2/1\n");
    const SceneDescription d = load_from_file("m.obj");
    const Material* screen = nullptr;
    const Material* shiny = nullptr;
    for (const Material& m : d.materials) {
        if (m.name.find("screen") != std::string::npos) screen = &m;
        if (m.name.find("shiny") != std::string::npos) shiny = &m;
    }
    ASSERT_NE(screen, nullptr);
    ASSERT_NE(shiny, nullptr);
    EXPECT_EQ(screen->emission, glm::vec3(1.0f));
    ASSERT_GE(screen->emission_texture, 0);
    EXPECT_TRUE(d.textures[std::size_t(screen->emission_texture)].srgb);
    EXPECT_EQ(d.textures[std::size_t(screen->emission_texture)].texels->rgba[7], glm::vec4(1.0f));
    EXPECT_EQ(d.textures[std::size_t(screen->emission_texture)].texels->rgba[0], glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
    EXPECT_EQ(shiny->emission_texture, -1);
    EXPECT_FALSE(shiny->is_emissive());
    bool screen_note = false, shiny_note = false;
    for (const std::string& note : d.notes) {
        screen_note = screen_note || note.find("screen:") != std::string::npos;
        shiny_note = shiny_note || (note.find("shiny") != std::string::npos && note.find("map_Ke texture") != std::string::npos);
    }
    EXPECT_FALSE(screen_note);
    EXPECT_TRUE(shiny_note);
}

TEST_F(TextureImport, SceneFileAlbedoTextureOnAQuad) {
    half_black_png(8, 8);
    const std::string quad = R"({"type": "quad", "vertices": [[-4, -4, 0], [4, -4, 0], [4, 4, 0], [-4, 4, 0]], "material": "panel"})";
    const SceneDescription d = load(quad, R"({"panel": {"type": "lambertian", "albedo": {"texture": "texture.png", "wrap": "clamp"}}})");
    ASSERT_EQ(d.textures.size(), 1u);
    EXPECT_EQ(d.textures[0].wrap_s, TextureWrap::clamp);
    EXPECT_TRUE(d.textures[0].srgb);  // a PNG; an EXR's values are linear
    EXPECT_FALSE(colour_file_is_srgb("wood.EXR"));
    EXPECT_FALSE(colour_file_is_srgb("sky.hdr"));
    EXPECT_TRUE(colour_file_is_srgb("wood.jpg"));
    EXPECT_EQ(d.materials[0].albedo, glm::vec3(1.0f));  // no factor: white
    EXPECT_EQ(d.meshes[0].uvs.size(), 4u);
    expect_halves_render_as_their_colours(d);
    // The factor multiplies, on principled materials too.
    const SceneDescription p = load(quad, R"({"panel": {"type": "principled", "metallic": 0, "roughness": 0.5,
        "base_color": {"texture": "texture.png", "factor": [0.5, 0.25, 1]}}})");
    EXPECT_EQ(p.materials[0].base_color, glm::vec3(0.5f, 0.25f, 1.0f));
    EXPECT_EQ(p.materials[0].color_texture, 0);

    // Bad input: the message names the field and the file.
    const auto error_for = [&](const std::string& materials) {
        try {
            load(quad, materials);
        } catch (const SceneError& e) {
            return std::string(e.what());
        }
        ADD_FAILURE() << "no SceneError for " << materials;
        return std::string();
    };
    std::string message = error_for(R"({"panel": {"type": "lambertian", "albedo": {"texture": "wood.png"}}})");
    EXPECT_NE(message.find("materials.panel.albedo.texture"), std::string::npos) << message;
    EXPECT_NE(message.find("wood.png"), std::string::npos) << message;
    write("corrupt.png", "\x89PNG\r\n\x1a\n but nothing after the signature");
    message = error_for(R"({"panel": {"type": "lambertian", "albedo": {"texture": "corrupt.png"}}})");
    EXPECT_NE(message.find("materials.panel.albedo.texture"), std::string::npos) << message;
    EXPECT_NE(message.find("corrupt.png"), std::string::npos) << message;
    message = error_for(R"({"panel": {"type": "lambertian", "albedo": {"texture": "texture.png", "wrap": "tile"}}})");
    EXPECT_NE(message.find("materials.panel.albedo.wrap"), std::string::npos) << message;
    message = error_for(R"({"panel": {"type": "lambertian", "albedo": {"file": "texture.png"}}})");
    EXPECT_NE(message.find("materials.panel.albedo"), std::string::npos) << message;
}

}  // namespace
}  // namespace wt
