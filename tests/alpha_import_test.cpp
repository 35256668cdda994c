// glTF's alphaMode, alphaCutoff and baseColorFactor's alpha as the loader maps them (glTF 2.0,
// 3.9.4): MASK and BLEND become alpha-tested materials, OPAQUE ignores alpha; a negative cutoff
// or an unknown mode is an error naming the file and the material; an alpha factor outside
// [0, 1] is clamped with a note; and a MASK square whose alpha is below its cutoff lets the
// camera see what is behind it, where the same square OPAQUE does not. MTL's dissolve: d as
// BLEND's alpha (not on glass), map_d's coverage from a grey image's value, an RGBA image's alpha
// or the channel -imfchan names, and a masked OBJ square cut where its mask is black.

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <functional>
#include <optional>
#include <stdexcept>

#include <gtest/gtest.h>

#include "core/scene_file/scene_error.h"
#include "import_gltf_files.h"
#include "lights_test_scenes.h"
#include "render_helpers.h"
#include "test_image_files.h"

namespace wt {
namespace {

using test::GltfFile;
using Json = nlohmann::json;

class AlphaImport : public test::ImportTest {
protected:
    // A square of side 8 in the z = 0 plane facing +z, its one material `material`, as a .glb
    // named `name`, loaded with the file's materials.
    // shared: two nodes place the square's mesh, the second 10 along x.
    void write_square(const Json& material, const std::string& name = "square.glb", bool shared = false) {
        GltfFile file;
        const int positions = file.positions({{-4, -4, 0}, {4, -4, 0}, {4, 4, 0}, {-4, 4, 0}});
        const int indices = file.indices({0, 1, 2, 0, 2, 3}, 5125);
        file.primitive({{"attributes", {{"POSITION", positions}}}, {"indices", indices}, {"material", 0}});
        Json j = file.json("");
        j["materials"] = {material};
        if (shared) {
            j["nodes"].push_back({{"mesh", 0}, {"translation", {10, 0, 0}}});
            j["scenes"][0]["nodes"] = {0, 1};
        }
        write(name, test::glb(j.dump(), file.bin()));
    }
    SceneDescription load_square(const Json& material, const std::string& name = "square.glb", bool shared = false) {
        write_square(material, name, shared);
        return load(R"({"type": "mesh_file", "file": ")" + name + R"(", "material": "from_file"})");
    }

    std::string error_for_square(const Json& material) {
        try {
            load_square(material);
        } catch (const SceneError& e) {
            return e.what();
        }
        ADD_FAILURE() << "no SceneError for " << material.dump();
        return "";
    }

    // An MTL file of the given text and an OBJ square of side 2 in the z = 0 plane facing +z,
    // its coordinates u = 0 at x = -1 and 1 at x = +1, using material `use`.
    void write_obj_square(const std::string& mtl, const std::string& use) {
        write("m.mtl", mtl);
        write("m.obj", "mtllib m.mtl\nv -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nusemtl " + use +
                           "\nf 1/1 2/2 3/3\nf 1/1 3/3 4/4\n");
    }

    // A copy: callers pass the temporary load_square() returns.
    static Material square_material(const SceneDescription& d) { return d.materials[d.meshes.back().material]; }
};

// cutoff: written only if given (std::nullopt: the file leaves it out).
Json material(const std::string& mode, double alpha, std::optional<double> cutoff = std::nullopt) {
    Json m = {{"name", "leaf"}, {"alphaMode", mode}, {"pbrMetallicRoughness", {{"baseColorFactor", {0.5, 0.5, 0.5, alpha}}, {"metallicFactor", 0.0}}}};
    if (cutoff) m["alphaCutoff"] = *cutoff;
    return m;
}

bool any_note_has(const SceneDescription& d, const std::string& text) {
    for (const std::string& note : d.notes)
        if (note.find(text) != std::string::npos) return true;
    return false;
}

TEST_F(AlphaImport, ModesCutoffAndFactorAreMapped) {
    const SceneDescription mask = load_square(material("MASK", 0.8, 0.3));
    const Material m = square_material(mask);
    EXPECT_EQ(m.alpha_mode, AlphaMode::mask);
    EXPECT_EQ(m.alpha_cutoff, 0.3f);
    EXPECT_EQ(m.alpha_factor, 0.8f);
    EXPECT_EQ(m.alpha_texture, -1);
    EXPECT_FALSE(any_note_has(mask, "alphaMode"));

    const Material default_cutoff = square_material(load_square(material("MASK", 0.8)));
    EXPECT_EQ(default_cutoff.alpha_cutoff, 0.5f);  // the specification's default
    EXPECT_EQ(square_material(load_square(material("BLEND", 0.25))).alpha_mode, AlphaMode::blend);
    const Material opaque = square_material(load_square(material("OPAQUE", 0.0)));
    EXPECT_EQ(opaque.alpha_mode, AlphaMode::opaque);
    EXPECT_FALSE(opaque.is_alpha_tested());

    // An emitting cut-out is noted: the light samples know nothing of its holes.
    Json glowing = material("MASK", 0.5);
    glowing["emissiveFactor"] = {1, 1, 1};
    EXPECT_TRUE(any_note_has(load_square(glowing), "alpha of an emitting material"));
    EXPECT_FALSE(any_note_has(mask, "alpha of an emitting material"));

    // A factor outside [0, 1] is clamped, with a note.
    const SceneDescription over = load_square(material("MASK", 1.5));
    EXPECT_EQ(square_material(over).alpha_factor, 1.0f);
    EXPECT_TRUE(any_note_has(over, "baseColorFactor alpha outside [0, 1] (clamped)"));
}

TEST_F(AlphaImport, BadCutoffAndModeAreErrorsNamingFileAndMaterial) {
    for (const Json& bad : {material("MASK", 1.0, -0.25), material("BLEND", 1.0, -1e-30)}) {
        const std::string e = error_for_square(bad);
        EXPECT_NE(e.find("square.glb"), std::string::npos) << e;
        EXPECT_NE(e.find("material \"leaf\""), std::string::npos) << e;
        EXPECT_NE(e.find("alphaCutoff"), std::string::npos) << e;
    }
    const std::string e = error_for_square(material("CUTOUT", 1.0));
    EXPECT_NE(e.find("square.glb"), std::string::npos) << e;
    EXPECT_NE(e.find("material \"leaf\""), std::string::npos) << e;
    EXPECT_NE(e.find("alphaMode \"CUTOUT\""), std::string::npos) << e;
    // OPAQUE ignores the cutoff, as it ignores alpha.
    EXPECT_EQ(square_material(load_square(material("OPAQUE", 1.0, 0.0))).alpha_mode, AlphaMode::opaque);
}

TEST_F(AlphaImport, SharedMaskedMeshIsInstancedAndSoIsANamedOne) {
    // The alpha test reads an instanced mesh's own coordinates: a mesh two nodes share is placed
    // by instances whether it is alpha-tested or not.
    for (const char* mode : {"OPAQUE", "MASK", "BLEND"}) {
        const SceneDescription d = load_square(material(mode, 1.0), std::string(mode) + ".glb", true);
        EXPECT_EQ(d.instances.size(), 2u) << mode;
        ASSERT_EQ(d.prototypes.size(), 1u) << mode;
        EXPECT_EQ(d.materials[d.prototypes[0].parts[0].material].is_alpha_tested(), std::string(mode) != "OPAQUE");
    }
    // A named mesh of the scene file that is alpha-tested is placed by its instance too.
    write_square(material("MASK", 1.0), "leaf.glb");
    const std::string text = R"({"camera": {"eye": [-5, 0, 0], "look_at": [0, 0, 0]}, "materials": )" + std::string(kMaterials) +
                             R"(, "meshes": {"leaf": {"type": "mesh_file", "file": "leaf.glb", "material": "from_file"}},
                                 "shapes": [{"type": "instance", "of": "leaf", "transforms": [{"translate": [0, 0, 1]}]}]})";
    const SceneDescription named = parse_scene_json(text, path("scene.json"));
    EXPECT_EQ(named.instances.size(), 1u);
    ASSERT_EQ(named.prototypes.size(), 1u);
    EXPECT_TRUE(named.materials[named.prototypes[0].parts[0].material].is_alpha_tested());
}

const Material& material_named(const SceneDescription& d, const std::string& suffix) {
    for (const Material& m : d.materials)
        if (m.name.size() >= suffix.size() && m.name.compare(m.name.size() - suffix.size(), suffix.size(), suffix) == 0) return m;
    throw std::runtime_error("test bug: no material " + suffix);
}

TEST_F(AlphaImport, MtlDissolveIsStochasticTransparencyButOnGlass) {
    // README, Alpha: d below 1 is alpha d, rendered as BLEND; d 1 (and no d) stays opaque; a
    // glass's d is its exporter's note of the glass and stays a note; d 0 is followed and noted.
    write_obj_square(
                     "newmtl faded\nKd 0.5 0.5 0.5\nd 0.25\nnewmtl solid\nKd 0.5 0.5 0.5\nd 1\nnewmtl plain\nKd 0.5 0.5 0.5\n"
                     "newmtl window\nillum 4\nNi 1.5\nd 0.5\nnewmtl gone\nKd 0.5 0.5 0.5\nd 0\nnewmtl mirror\nillum 3\nKs 1 1 1\nd 0.5\n",
                     "faded");
    const SceneDescription d = load(R"({"type": "mesh_file", "file": "m.obj", "material": "from_file"})");
    EXPECT_EQ(material_named(d, "faded").alpha_mode, AlphaMode::blend);
    EXPECT_EQ(material_named(d, "faded").alpha_factor, 0.25f);
    EXPECT_EQ(material_named(d, "faded").alpha_texture, -1);
    EXPECT_EQ(material_named(d, "mirror").alpha_mode, AlphaMode::blend);
    EXPECT_EQ(material_named(d, "mirror").alpha_factor, 0.5f);
    EXPECT_EQ(material_named(d, "gone").alpha_mode, AlphaMode::blend);
    EXPECT_EQ(material_named(d, "gone").alpha_factor, 0.0f);
    for (const char* opaque : {"solid", "plain", "window"}) EXPECT_FALSE(material_named(d, opaque).is_alpha_tested()) << opaque;
    EXPECT_EQ(material_named(d, "window").type, MaterialType::glass);
    bool window = false, gone = false, faded = false;
    for (const std::string& note : d.notes) {
        window = window || (note.find("window: d (dissolve) on a refracting material") != std::string::npos);
        gone = gone || (note.find("gone: d 0: the material is invisible") != std::string::npos);
        faded = faded || (note.find("faded:") != std::string::npos);
    }
    EXPECT_TRUE(window);
    EXPECT_TRUE(gone);
    EXPECT_FALSE(faded);  // mapped, so not named
}

TEST_F(AlphaImport, MtlMapDReadsAlphaOrLuminanceOrTheNamedChannel) {
    // A grey image's value, an RGBA image's alpha (not its grey colour), the red channel where
    // -imfchan r names it, each times d; a missing file is an error naming the OBJ file, the
    // material, map_d and the image.
    write("grey.pgm", test::pgm(4, 2, [](int x) { return uint8_t(x * 85); }));
    write("rgba.tga", test::tga_rgba(4, 2, [](int x) { return std::array<uint8_t, 4>{255, 255, uint8_t(51 * x), uint8_t(255 - 85 * x)}; }));
    write_obj_square(
                     "newmtl grey\nKd 1 1 1\nmap_d grey.pgm\nnewmtl rgba\nKd 1 1 1\nd 0.5\nmap_d rgba.tga\n"
                     "newmtl blue\nKd 1 1 1\nmap_d -imfchan b rgba.tga\nnewmtl coloured\nKd 1 1 1\nmap_Kd rgba.tga\n",
                     "grey");
    const SceneDescription d = load(R"({"type": "mesh_file", "file": "m.obj", "material": "from_file"})");
    const auto alphas = [&](const std::string& name) {
        const Material& m = material_named(d, name);
        EXPECT_EQ(m.alpha_mode, AlphaMode::blend) << name;
        std::vector<float> row;
        if (m.alpha_texture < 0) return row;
        EXPECT_NE(m.alpha_texture, m.color_texture) << name;
        const TextureImage& t = d.textures[std::size_t(m.alpha_texture)];
        EXPECT_FALSE(t.srgb) << name;
        for (int x = 0; x < 4; ++x) row.push_back(t.texels->rgba[std::size_t(x)].w);
        return row;
    };
    // 8-bit values / 255, whichever way the reader rounds that quotient.
    const auto expect_values = [&](const std::string& name, const std::vector<int>& bytes) {
        const std::vector<float> got = alphas(name);
        ASSERT_EQ(got.size(), bytes.size()) << name;
        for (std::size_t i = 0; i < got.size(); ++i) EXPECT_NEAR(got[i], bytes[i] / 255.0f, 1e-6f) << name << " " << i;
    };
    expect_values("grey", {0, 85, 170, 255});
    expect_values("rgba", {255, 170, 85, 0});
    expect_values("blue", {0, 51, 102, 153});
    EXPECT_EQ(material_named(d, "grey").alpha_factor, 1.0f);
    EXPECT_EQ(material_named(d, "rgba").alpha_factor, 0.5f);
    // The colour as the file stores it, not premultiplied by its alpha (OpenImageIO's default
    // for TGA and PNG): blue 0.6 where alpha is 0, as the blue coverage above reads it too.
    const Material& coloured = material_named(d, "coloured");
    ASSERT_GE(coloured.color_texture, 0);
    const glm::vec4 texel = d.textures[std::size_t(coloured.color_texture)].texels->rgba[3];
    EXPECT_NEAR(texel.z, 153 / 255.0f, 1e-6f);
    EXPECT_EQ(texel.w, 0.0f);

    write_obj_square("newmtl leaf\nKd 1 1 1\nmap_d nowhere.png\n", "leaf");
    try {
        load(R"({"type": "mesh_file", "file": "m.obj", "material": "from_file"})");
        ADD_FAILURE() << "a missing map_d loaded";
    } catch (const SceneError& e) {
        const std::string message = e.what();
        for (const char* part : {"m.obj", "material \"leaf\"", "map_d", "nowhere.png"})
            EXPECT_NE(message.find(part), std::string::npos) << part << " not in: " << message;
    }
}

TEST_F(AlphaImport, MtlMapDCutsTheSquareWhereItsMaskIsBlack) {
    // Seen from above under a constant environment of radiance 1, the square (u from 0.32 to 0.68
    // in view) with a mask black in its left half and white in its right: the two left columns
    // show the environment, exactly 1, where the opaque square does not; the two right columns
    // are the opaque square's bits (coverage 1 keeps every hit).
    const std::string mtl = "newmtl masked\nKd 0.5 0.5 0.5\nmap_d mask.pgm\nnewmtl opaque\nKd 0.5 0.5 0.5\n";
    write("mask.pgm", test::pgm(8, 8, [](int x) { return uint8_t(x < 4 ? 0 : 255); }));
    const auto render = [&](const std::string& use) {
        write_obj_square(mtl, use);
        SceneDescription d = load(R"({"type": "mesh_file", "file": "m.obj", "material": "from_file"})");
        test::view_from_above(d, 8, 16);
        return test::render_film(d, Integrator::wavefront).film;
    };
    const Film masked = render("masked"), opaque = render("opaque");
    double opaque_left = 0.0;
    for (uint32_t y = 0; y < 8; ++y) {
        for (uint32_t x : {0u, 1u}) {
            EXPECT_EQ(masked.pixel_mean(y * 8 + x), glm::dvec3(1.0)) << x << ", " << y;
            EXPECT_NE(opaque.pixel_mean(y * 8 + x), glm::dvec3(1.0)) << x << ", " << y;
            opaque_left += opaque.pixel_mean(y * 8 + x).x / 16.0;
        }
        for (uint32_t x : {6u, 7u}) EXPECT_EQ(masked.pixel_mean(y * 8 + x), opaque.pixel_mean(y * 8 + x)) << x << ", " << y;
    }
    // The square's albedo 0.5 under radiance 1 reflects 0.5; 16 pixels of 16 samples each are
    // within 0.3 of that by many of their standard deviations.
    EXPECT_LT(opaque_left, 0.8);
}

TEST_F(AlphaImport, MaskedSquareShowsWhatIsBehindIt) {
    // Seen from above under a constant environment of radiance 1: a square MASKed away (alpha
    // 0.3 < 0.5) shows the environment, exactly 1 in every pixel; OPAQUE with the same alpha
    // shows the square (which reflects less than 1), and so does MASK at cutoff 0.25.
    const auto render = [&](const Json& m) {
        SceneDescription d = load_square(m);
        test::view_from_above(d, 8, 4);
        return test::render_film(d, Integrator::wavefront).film;
    };
    const Film cut = render(material("MASK", 0.3));
    const Film opaque = render(material("OPAQUE", 0.3));
    const Film kept = render(material("MASK", 0.3, 0.25));
    for (uint32_t p = 0; p < 64; ++p) {
        EXPECT_EQ(cut.pixel_mean(p), glm::dvec3(1.0)) << p;
        EXPECT_LT(opaque.pixel_mean(p).x, 0.9) << p;
        EXPECT_EQ(kept.pixel_mean(p), opaque.pixel_mean(p)) << p;
    }
}

TEST_F(AlphaImport, KhronosClearCoatTestsBlendCoatingFromAssimpTestModels) {
    // The Khronos sample ClearCoatTest (Debian's assimp-testmodels): its "Partial_Coating" is a
    // black BLEND layer over a blue base, its alpha from PartialCoating_Alpha.png (0 to 255).
    const std::string file = "/usr/share/assimp/models/glTF2/ClearCoat-glTF/ClearCoatTest.gltf";
    if (!std::filesystem::exists(file)) GTEST_SKIP() << file << " is missing: install Debian's assimp-testmodels";
    SceneDescription d = load(R"({"type": "mesh_file", "file": ")" + file + R"(", "material": "from_file"})");
    int coating = -1;
    const std::string suffix = "/Partial_Coating";
    for (std::size_t i = 0; i < d.materials.size(); ++i) {
        const std::string& name = d.materials[i].name;
        if (name.size() >= suffix.size() && name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0) coating = int(i);
    }
    ASSERT_GE(coating, 0);
    const Material& m = d.materials[std::size_t(coating)];
    EXPECT_EQ(m.alpha_mode, AlphaMode::blend);
    ASSERT_GE(m.alpha_texture, 0);
    EXPECT_EQ(m.alpha_texture, m.color_texture);
    float lowest = 1.0f, highest = 0.0f;
    for (const glm::vec4& t : d.textures[std::size_t(m.alpha_texture)].texels->rgba)
        lowest = std::min(lowest, t.w), highest = std::max(highest, t.w);
    EXPECT_EQ(lowest, 0.0f);
    EXPECT_EQ(highest, 1.0f);

    // Rendered from the front under a white sky: the same bits for every schedule, ISA and
    // integrator, and another image than with the coating OPAQUE (all black where it covers).
    glm::vec3 lo(INFINITY), hi(-INFINITY);
    for (const TriangleMesh& mesh : d.meshes)
        for (const glm::vec3& v : mesh.vertices) lo = glm::min(lo, v), hi = glm::max(hi, v);
    const glm::vec3 centre = 0.5f * (lo + hi);
    d.lights = {test::constant_environment(glm::vec3(1.0f))};
    d.camera.look_at = centre;
    d.camera.eye = centre + glm::vec3(0.0f, 0.0f, 1.2f * std::max(hi.x - lo.x, hi.y - lo.y));
    d.camera.up = glm::vec3(0.0f, 1.0f, 0.0f);
    d.camera.fov_degrees = 50.0f;
    d.settings.width = d.settings.height = 24;
    d.settings.spp = 2;
    const Film film = test::render_film(d, Integrator::wavefront).film;
    test::expect_same_film_for_any_schedule(d, film);
    SceneDescription opaque = d;
    opaque.materials[std::size_t(coating)].alpha_mode = AlphaMode::opaque;
    EXPECT_FALSE(film == test::render_film(opaque, Integrator::wavefront).film);
    for (uint32_t p = 0; p < 24u * 24u; ++p) EXPECT_TRUE(std::isfinite(film.pixel_mean(p).x)) << p;
}

}  // namespace
}  // namespace wt
