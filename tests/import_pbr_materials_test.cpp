// glTF's metallic-roughness materials and MTL's PBR extension and Phong highlights, through the
// scene loader, to our principled, conductor and glass materials: each factor to its field,
// metallic 1 as the conductor, transmission as glass (rough where roughnessFactor is), factors
// outside [0, 1] clamped and named in the note, and no "partial metalness" note any more.

#include <array>
#include <cmath>
#include <string>

#include <nlohmann/json.hpp>

#include "import_gltf_files.h"
#include "core/scene_file/scene_error.h"
#include "import_test_files.h"

namespace {

using wt::Material;
using wt::MaterialType;
using wt::SceneDescription;
using Json = nlohmann::json;

using PbrImport = wt::test::ImportTest;

const Material& named(const SceneDescription& scene, const std::string& name) {
    for (const Material& m : scene.materials)
        if (m.name == name) return m;
    ADD_FAILURE() << "no material " << name;
    return scene.materials.front();
}

void expect_vec3_near(const glm::vec3& actual, const glm::vec3& expected) {
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(actual[c], expected[c], 1e-6f) << c;
}

// One triangle per material, each a primitive of the one mesh.
std::string gltf_with_materials(const Json& materials) {
    wt::test::GltfFile f;
    const int positions = f.positions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    for (std::size_t k = 0; k < materials.size(); ++k) f.primitive({{"attributes", {{"POSITION", positions}}}, {"material", k}});
    Json j = Json::parse(f.gltf());
    j["materials"] = materials;
    return j.dump();
}

TEST_F(PbrImport, GltfMetallicRoughnessMapsEachFactor) {
    const Json materials = {
        {{"name", "gold"}, {"pbrMetallicRoughness", {{"baseColorFactor", {1.0, 0.77, 0.34, 1}}, {"metallicFactor", 1}, {"roughnessFactor", 0.3}}}},
        {{"name", "half_copper"},
         {"pbrMetallicRoughness", {{"baseColorFactor", {0.95, 0.64, 0.54, 1}}, {"metallicFactor", 0.5}, {"roughnessFactor", 0.4}}}},
        {{"name", "plastic"},
         {"pbrMetallicRoughness", {{"baseColorFactor", {0.1, 0.2, 0.8, 1}}, {"metallicFactor", 0}, {"roughnessFactor", 0.2}}},
         {"extensions", {{"KHR_materials_ior", {{"ior", 1.45}}}}}},
        {{"name", "frosted"},
         {"pbrMetallicRoughness", {{"roughnessFactor", 0.5}}},
         {"extensions", {{"KHR_materials_transmission", {{"transmissionFactor", 1}}}, {"KHR_materials_ior", {{"ior", 1.33}}}}}},
        {{"name", "clear"},
         {"pbrMetallicRoughness", {{"roughnessFactor", 0}}},
         {"extensions", {{"KHR_materials_transmission", {{"transmissionFactor", 1}}}}}},
        {{"name", "lamp"},
         {"pbrMetallicRoughness", {{"metallicFactor", 1}, {"roughnessFactor", 0}}},
         {"emissiveFactor", {1, 0.5, 0.25}},
         {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 4}}}}}},
        {{"name", "defaults"}},
        {{"name", "bad"}, {"pbrMetallicRoughness", {{"metallicFactor", 1.5}, {"roughnessFactor", -0.2}}}}};
    write("m.gltf", gltf_with_materials(materials));
    const SceneDescription scene = load(R"({"type": "mesh_file", "file": "m.gltf", "material": "from_file"})");

    // Metallic 1: the conductor of F0 baseColorFactor.
    const Material& gold = named(scene, "m.gltf/gold");
    EXPECT_EQ(gold.type, MaterialType::rough_conductor);
    expect_vec3_near(gold.f0, {1.0f, 0.77f, 0.34f});
    EXPECT_FLOAT_EQ(gold.roughness, 0.3f);
    EXPECT_EQ(gold.eta.x, 0.0f);  // Schlick from F0, not a complex index

    const Material& copper = named(scene, "m.gltf/half_copper");
    EXPECT_EQ(copper.type, MaterialType::principled);
    expect_vec3_near(copper.base_color, {0.95f, 0.64f, 0.54f});
    EXPECT_FLOAT_EQ(copper.metallic, 0.5f);
    EXPECT_FLOAT_EQ(copper.roughness, 0.4f);
    EXPECT_FLOAT_EQ(copper.ior, 1.5f);  // glTF's default, no KHR_materials_ior
    EXPECT_EQ(copper.albedo, glm::vec3(0.0f));  // the diffuse materials' field stays unused

    const Material& plastic = named(scene, "m.gltf/plastic");
    EXPECT_EQ(plastic.type, MaterialType::principled);
    EXPECT_FLOAT_EQ(plastic.metallic, 0.0f);
    EXPECT_FLOAT_EQ(plastic.roughness, 0.2f);
    EXPECT_FLOAT_EQ(plastic.ior, 1.45f);

    const Material& frosted = named(scene, "m.gltf/frosted");
    EXPECT_EQ(frosted.type, MaterialType::rough_glass);
    EXPECT_FLOAT_EQ(frosted.roughness, 0.5f);
    EXPECT_FLOAT_EQ(frosted.ior, 1.33f);
    const Material& clear = named(scene, "m.gltf/clear");
    EXPECT_EQ(clear.type, MaterialType::glass);
    EXPECT_FLOAT_EQ(clear.ior, 1.5f);

    // An emitting metal keeps the principled material (conductors do not emit), metallic 1.
    const Material& lamp = named(scene, "m.gltf/lamp");
    EXPECT_EQ(lamp.type, MaterialType::principled);
    EXPECT_FLOAT_EQ(lamp.metallic, 1.0f);
    expect_vec3_near(lamp.emission, {4.0f, 2.0f, 1.0f});

    // glTF's defaults: white, metallic 1, roughness 1: a rough white metal.
    const Material& defaults = named(scene, "m.gltf/defaults");
    EXPECT_EQ(defaults.type, MaterialType::rough_conductor);
    EXPECT_EQ(defaults.f0, glm::vec3(1.0f));
    EXPECT_EQ(defaults.roughness, 1.0f);

    // Out of range: clamped (metallic 1.5 to 1, roughness -0.2 to the smooth conductor), and said.
    const Material& bad = named(scene, "m.gltf/bad");
    EXPECT_EQ(bad.type, MaterialType::conductor);
    EXPECT_EQ(bad.roughness, 0.0f);
    ASSERT_EQ(scene.notes.size(), 1u);
    const std::string& note = scene.notes[0];
    EXPECT_NE(note.find("not mapped from its materials: bad: roughnessFactor outside [0, 1] (clamped), "
                        "metallicFactor outside [0, 1] (clamped)"),
              std::string::npos)
        << note;
    EXPECT_EQ(note.find("metallicFactor > 0"), std::string::npos) << note;  // partial metalness is mapped now
    EXPECT_EQ(note.find("gold"), std::string::npos) << note;
}

// The textures we do not render are an honest note (texture_import_test has those we do); a
// texture we would render that the file does not define is an error naming it.
TEST_F(PbrImport, GltfTexturesNotRenderedStayAnHonestNote) {
    // (An emissiveTexture on glass: glass does not emit. texture_import_test has it rendered.)
    write("m.gltf", gltf_with_materials(Json::array({{{"name", "panel"},
                                                      {"occlusionTexture", {{"index", 0}}},
                                                      {"emissiveFactor", {1.0, 1.0, 1.0}},
                                                      {"emissiveTexture", {{"index", 0}}},
                                                      {"extensions", {{"KHR_materials_transmission", {{"transmissionFactor", 1.0}}}}}}})));
    const SceneDescription scene = load(R"({"type": "mesh_file", "file": "m.gltf", "material": "from_file"})");
    ASSERT_EQ(scene.notes.size(), 1u);
    EXPECT_NE(scene.notes[0].find("panel: "), std::string::npos) << scene.notes[0];
    EXPECT_NE(scene.notes[0].find("occlusionTexture"), std::string::npos) << scene.notes[0];
    EXPECT_NE(scene.notes[0].find("emissiveTexture"), std::string::npos) << scene.notes[0];
    write("bad.gltf", gltf_with_materials(Json::array(
                          {{{"name", "panel"}, {"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}})));
    try {
        load(R"({"type": "mesh_file", "file": "bad.gltf", "material": "from_file"})");
        ADD_FAILURE() << "no error for a baseColorTexture the file does not define";
    } catch (const wt::SceneError& e) {
        EXPECT_NE(std::string(e.what()).find("material \"panel\": baseColorTexture: texture 0 does not exist"), std::string::npos)
            << e.what();
    }
    // With a scene material in place of the file's, the file's textures are not read at all.
    EXPECT_NO_THROW(load(R"({"type": "mesh_file", "file": "bad.gltf", "material": "white"})"));
}

TEST_F(PbrImport, MtlPbrExtensionAndPhongHighlights) {
    write("m.mtl",
          "newmtl brushed\nKd 0.9 0.8 0.7\nPm 1\nPr 0.35\n"
          "newmtl satin\nKd 0.2 0.4 0.6\nPm 0.25\nPr 0.5\nKe 1 1 1\n"
          "newmtl shiny\nillum 2\nKd 0.5 0.5 0.5\nKs 0.5 0.5 0.5\nNs 250\n"
          "newmtl matte\nillum 2\nKd 0.5 0.5 0.5\nKs 0 0 0\nNs 250\n"
          "newmtl flat\nillum 1\nKd 0.5 0.5 0.5\nKs 1 1 1\n"
          "newmtl frosted\nillum 7\nNi 1.4\nPr 0.6\n"
          "newmtl over\nKd 0.5 0.5 0.5\nPm 2\nPr 0.5\n");
    std::string obj = "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\n";
    for (const char* name : {"brushed", "satin", "shiny", "matte", "flat", "frosted", "over"})
        obj += std::string("usemtl ") + name + "\nf 1 2 3\n";
    write("m.obj", obj);
    const SceneDescription scene = load(R"({"type": "mesh_file", "file": "m.obj", "material": "from_file"})");

    const Material& brushed = named(scene, "m.obj/brushed");  // Pm 1: the conductor of F0 Kd
    EXPECT_EQ(brushed.type, MaterialType::rough_conductor);
    expect_vec3_near(brushed.f0, {0.9f, 0.8f, 0.7f});
    EXPECT_FLOAT_EQ(brushed.roughness, 0.35f);

    const Material& satin = named(scene, "m.obj/satin");
    EXPECT_EQ(satin.type, MaterialType::principled);
    expect_vec3_near(satin.base_color, {0.2f, 0.4f, 0.6f});
    EXPECT_FLOAT_EQ(satin.metallic, 0.25f);
    EXPECT_FLOAT_EQ(satin.roughness, 0.5f);
    EXPECT_EQ(satin.emission, glm::vec3(1.0f));

    // Ns 250: 1 - sqrt(250 / 1000) = 0.5, Blender's conversion.
    const Material& shiny = named(scene, "m.obj/shiny");
    EXPECT_EQ(shiny.type, MaterialType::principled);
    EXPECT_FLOAT_EQ(shiny.metallic, 0.0f);
    EXPECT_FLOAT_EQ(shiny.roughness, 0.5f);
    expect_vec3_near(shiny.base_color, glm::vec3(0.5f));

    // No highlight (Ks black, or illum 1 which has none): Lambert, as before.
    EXPECT_EQ(named(scene, "m.obj/matte").type, MaterialType::lambertian);
    EXPECT_EQ(named(scene, "m.obj/flat").type, MaterialType::lambertian);

    const Material& frosted = named(scene, "m.obj/frosted");
    EXPECT_EQ(frosted.type, MaterialType::rough_glass);
    EXPECT_FLOAT_EQ(frosted.roughness, 0.6f);
    EXPECT_FLOAT_EQ(frosted.ior, 1.4f);

    EXPECT_EQ(named(scene, "m.obj/over").type, MaterialType::rough_conductor);  // Pm 2 clamped to 1
    ASSERT_EQ(scene.notes.size(), 1u);
    EXPECT_NE(scene.notes[0].find("shiny: Ks (the specular is a dielectric's"), std::string::npos) << scene.notes[0];
    EXPECT_NE(scene.notes[0].find("over: Pm outside [0, 1] (clamped)"), std::string::npos) << scene.notes[0];
}

}  // namespace
