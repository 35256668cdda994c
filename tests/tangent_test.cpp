// Normal-map tangents: MikkTSpace (core/geometry/mikktspace_tangents.h) on a flat quad (the
// coordinates' own frame), on a mirrored UV island (the other handedness, the mapped normal
// turned the right way on both sides) and on a cylinder with a seam (unit, orthogonal, shared
// by the corners of a vertex, finite where the coordinates are degenerate); glTF's TANGENT read
// and preferred, made where a file has none, a bad one refused or replaced; and tangents placed
// by instances, a mirroring placement flipping their handedness.

#include <cmath>
#include <fstream>
#include <sstream>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "core/film/image_output.h"
#include "core/geometry/mikktspace_tangents.h"
#include "core/import/place_mesh.h"
#include "core/scene/material_at_hit.h"
#include "core/scene_file/scene_error.h"
#include "import_gltf_files.h"
#include "instance_scenes.h"
#include "kernels/memory_estimate.h"
#include "lights_test_scenes.h"
#include "render_helpers.h"
#include "texture_test_images.h"

namespace wt {
namespace {

using test::GltfFile;
using Json = nlohmann::json;

constexpr float kPi = 3.14159265358979f;

// A normal 37 degrees from the surface's, leaning towards +u (0.48 of the tangent) and the
// image's up (0.36 of the bitangent, which w decides).
TextureImage leaning() {
    return test::texture_of(2, 2, [](int, int) { return glm::vec4(0.5f + 0.5f * 0.48f, 0.5f + 0.5f * 0.36f, 0.5f + 0.5f * 0.8f, 1.0f); });
}

// The shading normal a normal-mapped hit at barycentrics (u, v) of triangle `prim` gets.
glm::vec3 mapped_normal(const Scene& scene, uint32_t prim, float u = 0.25f, float v = 0.25f) {
    Hit hit;
    hit.prim = prim, hit.u = u, hit.v = v, hit.t = 1.0f;
    Ray ray;
    ray.origin = glm::vec3(0.0f), ray.direction = glm::vec3(0.0f, 0.0f, -1.0f);
    SurfacePoint surface = surface_at(scene, ray, hit);
    Material m = scene.materials[surface.material];
    apply_textures(scene, hit, surface, ray, false, m);
    return surface.shading_normal;
}

// The 8 x 8 square facing +z of the texture tests: u along +x, v = 0 at y = +4.
const std::vector<glm::vec3> kSquare = {{-4, -4, 0}, {4, -4, 0}, {4, 4, 0}, {-4, 4, 0}};
const std::vector<glm::vec2> kSquareUvs = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};
const std::vector<std::array<uint32_t, 3>> kSquareTriangles = {{0, 1, 2}, {0, 2, 3}};

// Two squares side by side, indexed over 6 vertices: x in [0, 4] has u = x / 4, x in [-4, 0]
// the mirror image u = -x / 4 (a UV island flipped, as symmetric models share one half's texels).
const std::vector<glm::vec3> kMirrored = {{-4, -4, 0}, {0, -4, 0}, {4, -4, 0}, {-4, 4, 0}, {0, 4, 0}, {4, 4, 0}};
const std::vector<glm::vec2> kMirroredUvs = {{1, 1}, {0, 1}, {1, 1}, {1, 0}, {0, 0}, {1, 0}};
const std::vector<std::array<uint32_t, 3>> kMirroredTriangles = {{1, 2, 5}, {1, 5, 4}, {0, 1, 4}, {0, 4, 3}};  // right, then left

TEST(MikkTSpace, FlatQuadIsTheCoordinatesFrame) {
    const std::vector<glm::vec3> up(4, glm::vec3(0, 0, 1));
    // u along +x: the tangent dP/du is +x, and -dP/dv (+y) is cross(N, T): w = +1.
    for (const glm::vec4& t : mikktspace_tangents(kSquare, up, kSquareUvs, kSquareTriangles)) EXPECT_EQ(t, glm::vec4(1, 0, 0, 1));
    // The coordinates turned a quarter: u along +y, v along +x, so -dP/dv = -x = cross(N, +y).
    const std::vector<glm::vec2> turned = {{0, 0}, {0, 1}, {1, 1}, {1, 0}};
    for (const glm::vec4& t : mikktspace_tangents(kSquare, up, turned, kSquareTriangles)) EXPECT_EQ(t, glm::vec4(0, 1, 0, 1));
    // Without normals, each face's own (the same here).
    for (const glm::vec4& t : mikktspace_tangents(kSquare, {}, kSquareUvs, kSquareTriangles)) EXPECT_EQ(t, glm::vec4(1, 0, 0, 1));
}

TEST(MikkTSpace, MirroredIslandHasTheOtherHandedness) {
    const std::vector<glm::vec3> up(6, glm::vec3(0, 0, 1));
    const std::vector<glm::vec4> t = mikktspace_tangents(kMirrored, up, kMirroredUvs, kMirroredTriangles);
    // The seam's vertices (x = 0) weld, but each side keeps its own: +u is -x on the left.
    for (int c = 0; c < 6; ++c) EXPECT_EQ(t[std::size_t(c)], glm::vec4(1, 0, 0, 1)) << c;
    for (int c = 6; c < 12; ++c) EXPECT_EQ(t[std::size_t(c)], glm::vec4(-1, 0, 0, -1)) << c;
}

TEST(MikkTSpace, CylinderWithASeamAndDegenerateCoordinates) {
    // P = (cos a, y, sin a), a = 2 pi i / n, i = 0..n (i = n the seam's copy of i = 0, u = 1),
    // y in {0, 1} (v = 1 - y); outward normals, winding facing out.
    const int n = 12;
    std::vector<glm::vec3> p, normals;
    std::vector<glm::vec2> uv;
    for (int row = 0; row < 2; ++row)
        for (int i = 0; i <= n; ++i) {
            const float a = 2.0f * kPi * float(i) / float(n);
            p.push_back({std::cos(a), float(row), std::sin(a)});
            normals.push_back({std::cos(a), 0.0f, std::sin(a)});
            uv.push_back({float(i) / float(n), 1.0f - float(row)});
        }
    std::vector<std::array<uint32_t, 3>> triangles;
    for (uint32_t i = 0; i < uint32_t(n); ++i) {
        const uint32_t a = i, b = i + 1, c = i + uint32_t(n) + 1, d = c + 1;
        triangles.push_back({a, d, b});
        triangles.push_back({a, c, d});
    }
    // A face whose three coordinates are equal, sharing vertex 0 (position, normal and
    // coordinates) with the ring, and one with no good face at any corner.
    const uint32_t q = uint32_t(p.size());
    for (glm::vec3 x : {glm::vec3(0.5f, 0.5f, 0.0f), glm::vec3(0.5f, 0.2f, 0.3f)}) p.push_back(x), normals.push_back({1, 0, 0}), uv.push_back(uv[0]);
    triangles.push_back({0, q, q + 1});
    const uint32_t alone = uint32_t(p.size());
    for (glm::vec3 x : {glm::vec3(3, 0, 0), glm::vec3(3, 1, 0), glm::vec3(3, 0, 1)}) p.push_back(x), normals.push_back({0, 0, 1}), uv.push_back({0.5f, 0.5f});
    triangles.push_back({alone, alone + 1, alone + 2});

    const std::vector<glm::vec4> t = mikktspace_tangents(p, normals, uv, triangles);
    ASSERT_EQ(t.size(), 3 * triangles.size());
    std::vector<glm::vec4> of_vertex(p.size(), glm::vec4(0.0f));
    for (std::size_t f = 0; f < triangles.size(); ++f)
        for (int c = 0; c < 3; ++c) {
            const glm::vec4& g = t[3 * f + std::size_t(c)];
            const uint32_t v = triangles[f][std::size_t(c)];
            ASSERT_TRUE(std::isfinite(g.x) && std::isfinite(g.y) && std::isfinite(g.z)) << f;
            EXPECT_NEAR(glm::length(glm::vec3(g)), 1.0f, 1e-5f) << f;
            EXPECT_NEAR(glm::dot(glm::vec3(g), normals[v]), 0.0f, 1e-5f) << f;
            EXPECT_TRUE(g.w == 1.0f || g.w == -1.0f) << f;
            // Continuous: every corner of a vertex has the vertex's one tangent.
            if (of_vertex[v].w == 0.0f) of_vertex[v] = g;
            EXPECT_EQ(g, of_vertex[v]) << "vertex " << v << " face " << f;
        }
    for (int row = 0; row < 2; ++row)
        for (int i = 0; i <= n; ++i) {
            // dP/du points along the circle, and -dP/dv (+y) is -cross(N, T): w = -1.
            const float a = 2.0f * kPi * float(i) / float(n);
            const glm::vec4& g = of_vertex[std::size_t(row * (n + 1) + i)];
            EXPECT_NEAR(g.x, -std::sin(a), 1e-4f) << i;
            EXPECT_NEAR(g.y, 0.0f, 1e-4f) << i;
            EXPECT_NEAR(g.z, std::cos(a), 1e-4f) << i;
            EXPECT_EQ(g.w, -1.0f) << i;
        }
    // The seam's two copies of a vertex (the same position and normal, u 0 and 1) agree.
    EXPECT_LT(glm::distance(glm::vec3(of_vertex[0]), glm::vec3(of_vertex[std::size_t(n)])), 1e-4f);
    // The degenerate face's corner at vertex 0 took the ring's tangent there.
    EXPECT_EQ(t[3 * std::size_t(2 * n)], of_vertex[0]);
}

class TangentImport : public test::ImportTest {
protected:
    // A 2 x 2 grey PNG's bytes (the normal map's image; the tests put their own texels in).
    std::string grey_png() const {
        write_image(path("grey.png"), 2, 2, std::vector<float>(12, 0.5f));
        std::ifstream in(path("grey.png"), std::ios::binary);
        std::stringstream bytes;
        bytes << in.rdbuf();
        return bytes.str();
    }

    // A glTF mesh (normals +z) whose material "bumpy" has a normal map, TANGENT `tangent` when
    // given (an accessor's JSON is filled in by `edit`).
    Json mesh(GltfFile& file, const std::vector<glm::vec3>& p, const std::vector<glm::vec2>& uv,
              const std::vector<std::array<uint32_t, 3>>& triangles, const std::vector<glm::vec4>& tangents = {},
              int tangent_type = 5126, const char* tangent_shape = "VEC4") {
        std::vector<std::array<float, 3>> points;
        test::Bytes normal_bytes, uv_bytes, tangent_bytes;
        for (std::size_t i = 0; i < p.size(); ++i) {
            points.push_back({p[i].x, p[i].y, p[i].z});
            for (float f : {0.0f, 0.0f, 1.0f}) normal_bytes.put(f);
            uv_bytes.put(uv[i].x), uv_bytes.put(uv[i].y);
        }
        Json attributes = {{"POSITION", file.positions(points)}};
        attributes["NORMAL"] = file.accessor({{"bufferView", file.view(normal_bytes.str())}, {"componentType", 5126}, {"count", p.size()}, {"type", "VEC3"}});
        attributes["TEXCOORD_0"] = file.accessor({{"bufferView", file.view(uv_bytes.str())}, {"componentType", 5126}, {"count", p.size()}, {"type", "VEC2"}});
        if (!tangents.empty()) {
            for (const glm::vec4& t : tangents)
                for (int c = 0; c < (std::string(tangent_shape) == "VEC3" ? 3 : 4); ++c)
                    if (tangent_type == 5126) tangent_bytes.put(t[c]);
                    else tangent_bytes.put(uint16_t(t[c] * 100.0f + 200.0f));
            attributes["TANGENT"] = file.accessor({{"bufferView", file.view(tangent_bytes.str())},
                                                   {"componentType", tangent_type},
                                                   {"count", tangents.size()},
                                                   {"type", tangent_shape}});
        }
        std::vector<uint32_t> flat;
        for (const auto& tri : triangles) flat.insert(flat.end(), tri.begin(), tri.end());
        file.primitive({{"attributes", attributes}, {"indices", file.indices(flat, 5125)}, {"material", 0}});
        const int png = file.view(grey_png());
        Json j = file.json("");
        j["materials"] = {{{"name", "bumpy"}, {"normalTexture", {{"index", 0}}}, {"pbrMetallicRoughness", {{"metallicFactor", 0.0}}}}};
        j["textures"] = {{{"source", 0}}};
        j["images"] = {{{"bufferView", png}, {"mimeType", "image/png"}}};
        return j;
    }

    // The file loaded with its materials, its normal map's texels a normal towards +u.
    SceneDescription load_bumpy(const std::string& name, const Json& j, const GltfFile& file) {
        write(name, test::glb(j.dump(), file.bin()));
        SceneDescription d = load(R"({"type": "mesh_file", "file": ")" + name + R"(", "material": "from_file"})");
        for (const Material& m : d.materials)
            if (m.normal_texture >= 0) d.textures[std::size_t(m.normal_texture)] = leaning();
        return d;
    }

    std::string error(const std::string& name, const Json& j, const GltfFile& file) {
        write(name, test::glb(j.dump(), file.bin()));
        try {
            load(R"({"type": "mesh_file", "file": ")" + name + R"(", "material": "from_file"})");
        } catch (const SceneError& e) {
            return e.what();
        }
        ADD_FAILURE() << "no error for " << name;
        return "";
    }
};

TEST_F(TangentImport, MadeWhereTheFileHasNoneAndTheSameBitsAsTheFilesOwn) {
    GltfFile made_file;
    SceneDescription made = load_bumpy("made.glb", mesh(made_file, kSquare, kSquareUvs, kSquareTriangles), made_file);
    ASSERT_EQ(made.meshes.size(), 1u);
    ASSERT_EQ(made.meshes[0].tangents.size(), 4u);
    for (const glm::vec4& t : made.meshes[0].tangents) EXPECT_EQ(t, glm::vec4(1, 0, 0, 1));
    GltfFile given_file;
    SceneDescription given = load_bumpy(
        "given.glb", mesh(given_file, kSquare, kSquareUvs, kSquareTriangles, std::vector<glm::vec4>(4, glm::vec4(1, 0, 0, 1))), given_file);
    EXPECT_EQ(given.meshes[0].tangents, made.meshes[0].tangents);
    test::view_from_above(made, 8, 4);
    test::view_from_above(given, 8, 4);
    const test::RenderedFilm rendered = test::render_film(made, Integrator::wavefront);
    EXPECT_TRUE(rendered.film == test::render_film(given, Integrator::wavefront).film);
    EXPECT_EQ(rendered.result.counts.nonfinite_samples, 0u);
    // The tangents are stored beside the coordinates, one per vertex, and the memory estimate
    // counts them.
    SceneDescription untangented = made;
    untangented.meshes[0].tangents.clear();
    const Scene with = build_scene(made), without = build_scene(untangented);
    ASSERT_EQ(with.triangles.vertex_count(), 4u);
    EXPECT_EQ(with.texture_coordinates.bytes(), without.texture_coordinates.bytes() + 4 * sizeof(glm::vec4));
    EXPECT_EQ(estimate_render_memory(with, RenderOptions{}).textures - estimate_render_memory(without, RenderOptions{}).textures,
              double(4 * sizeof(glm::vec4)));
    // And the normal map leans the normal towards +x, dP/du, and +y, -dP/dv.
    const glm::vec3 n = mapped_normal(build_scene(made), 0);
    EXPECT_NEAR(n.x, 0.48f, 1e-5f);
    EXPECT_NEAR(n.y, 0.36f, 1e-5f);
    EXPECT_NEAR(n.z, 0.8f, 1e-5f);
}

TEST_F(TangentImport, TheFilesTangentsAreUsed) {
    // The file's tangent is -y, a quarter turn from the coordinates' +x: the normal follows it
    // (the bitangent cross(N, T) is then +x).
    GltfFile file;
    const SceneDescription d = load_bumpy(
        "given.glb", mesh(file, kSquare, kSquareUvs, kSquareTriangles, std::vector<glm::vec4>(4, glm::vec4(0, -1, 0, 1))), file);
    for (const glm::vec4& t : d.meshes[0].tangents) EXPECT_EQ(t, glm::vec4(0, -1, 0, 1));
    const glm::vec3 n = mapped_normal(build_scene(d), 1);
    EXPECT_NEAR(n.y, -0.48f, 1e-5f);
    EXPECT_NEAR(n.x, 0.36f, 1e-5f);
    // Without them, +x (MikkTSpace's); the image differs.
    GltfFile plain_file;
    SceneDescription made = load_bumpy("made.glb", mesh(plain_file, kSquare, kSquareUvs, kSquareTriangles), plain_file);
    EXPECT_NEAR(mapped_normal(build_scene(made), 1).x, 0.48f, 1e-5f);
    EXPECT_NEAR(mapped_normal(build_scene(made), 1).y, 0.36f, 1e-5f);
    SceneDescription seen = d;
    test::view_from_above(seen, 8, 4);
    test::view_from_above(made, 8, 4);
    EXPECT_FALSE(test::render_film(seen, Integrator::wavefront).film == test::render_film(made, Integrator::wavefront).film);
}

TEST_F(TangentImport, MirroredIslandTurnsEachSideTheRightWay) {
    GltfFile file;
    const SceneDescription d = load_bumpy("mirrored.glb", mesh(file, kMirrored, kMirroredUvs, kMirroredTriangles), file);
    const TriangleMesh& m = d.meshes[0];
    // The seam's two vertices are split, each side's copy with its own handedness.
    ASSERT_EQ(m.vertices.size(), 8u);
    for (std::size_t tri = 0; tri < 4; ++tri)
        for (uint32_t v : m.triangles[tri]) EXPECT_EQ(m.tangents[v].w, tri < 2 ? 1.0f : -1.0f) << tri;
    // The map's normal leans towards +u, +x on the right half and -x on the mirrored left, and
    // up the image (+y) on both: there the left half's w = -1 keeps the bitangent at +y.
    const Scene scene = build_scene(d);
    for (uint32_t tri = 0; tri < 4; ++tri) {
        const glm::vec3 n = mapped_normal(scene, tri);
        EXPECT_NEAR(n.x, tri < 2 ? 0.48f : -0.48f, 1e-5f) << tri;
        EXPECT_NEAR(n.y, 0.36f, 1e-5f) << tri;
    }
}

TEST_F(TangentImport, BadTangentsAreRefusedOrReplaced) {
    const std::vector<glm::vec4> good(4, glm::vec4(1, 0, 0, 1));
    {
        GltfFile file;
        const Json j = mesh(file, kSquare, kSquareUvs, kSquareTriangles, good, 5126, "VEC3");
        test::expect_mesh_error(error("vec3.glb", j, file), "vec3.glb", "TANGENT of mesh 0 primitive 0");
    }
    {
        GltfFile file;
        const Json j = mesh(file, kSquare, kSquareUvs, kSquareTriangles, good, 5123);
        test::expect_mesh_error(error("short.glb", j, file), "short.glb", "TANGENT of mesh 0 primitive 0");
    }
    {
        GltfFile file;
        const Json j = mesh(file, kSquare, kSquareUvs, kSquareTriangles, std::vector<glm::vec4>(3, glm::vec4(1, 0, 0, 1)));
        test::expect_mesh_error(error("count.glb", j, file), "count.glb", "TANGENT and POSITION counts differ");
    }
    // NaN, zero and w = 0: a note, and the tangents made as if the file had none.
    for (const glm::vec4& bad : {glm::vec4(NAN, 0, 0, 1), glm::vec4(0, 0, 0, 1), glm::vec4(1, 0, 0, 0)}) {
        std::vector<glm::vec4> tangents = good;
        tangents[2] = bad;
        GltfFile file;
        SceneDescription d = load_bumpy("bad.glb", mesh(file, kSquare, kSquareUvs, kSquareTriangles, tangents), file);
        for (const glm::vec4& t : d.meshes[0].tangents) EXPECT_EQ(t, glm::vec4(1, 0, 0, 1));
        bool noted = false;
        for (const std::string& note : d.notes) noted |= note.find("TANGENT") != std::string::npos && note.find("bad.glb") != std::string::npos;
        EXPECT_TRUE(noted);
        test::view_from_above(d, 8, 2);
        EXPECT_EQ(test::render_film(d, Integrator::wavefront).result.counts.nonfinite_samples, 0u);
    }
}

TEST_F(TangentImport, DegenerateCoordinatesRenderFinite) {
    // Every coordinate the same: no face has a mapping, every tangent is made up, none is NaN.
    GltfFile file;
    SceneDescription d = load_bumpy("flat.glb", mesh(file, kSquare, std::vector<glm::vec2>(4, glm::vec2(0.5f)), kSquareTriangles), file);
    for (const glm::vec4& t : d.meshes[0].tangents) {
        EXPECT_TRUE(std::isfinite(t.x) && std::isfinite(t.y) && std::isfinite(t.z) && std::abs(t.w) == 1.0f);
        EXPECT_NEAR(glm::length(glm::vec3(t)), 1.0f, 1e-6f);
        EXPECT_EQ(t.z, 0.0f);
    }
    test::view_from_above(d, 8, 2);
    const test::RenderedFilm rendered = test::render_film(d, Integrator::wavefront);
    EXPECT_EQ(rendered.result.counts.nonfinite_samples, 0u);
    for (uint32_t p = 0; p < 64; ++p) EXPECT_TRUE(std::isfinite(rendered.film.pixel_mean(p).x)) << p;
}

TEST_F(TangentImport, ASharedMeshKeepsItsTangentsForItsInstances) {
    // One mesh placed by two nodes, the second mirrored: stored once, with its object-space
    // coordinates and tangents (instances place them at each hit).
    GltfFile file;
    Json j = mesh(file, kSquare, kSquareUvs, kSquareTriangles);
    j["nodes"] = {{{"mesh", 0}}, {{"mesh", 0}, {"scale", {-1.0, 1.0, 1.0}}, {"translation", {10.0, 0.0, 0.0}}}};
    j["scenes"][0]["nodes"] = {0, 1};
    const SceneDescription d = load_bumpy("shared.glb", j, file);
    ASSERT_EQ(d.prototypes.size(), 1u);
    ASSERT_EQ(d.instances.size(), 2u);
    const TriangleMesh& part = d.prototypes[0].parts[0];
    EXPECT_EQ(part.uvs.size(), 4u);
    ASSERT_EQ(part.tangents.size(), 4u);
    for (const glm::vec4& t : part.tangents) EXPECT_EQ(t, glm::vec4(1, 0, 0, 1));
    // The mirrored copy leans its normal towards its own +u, which the mirror sent to -x.
    const Scene scene = build_scene(d);
    const uint32_t first = scene.instances.first_id;
    for (uint32_t k = 0; k < 2; ++k) {
        const glm::vec3 n = mapped_normal(scene, first + 2 * k);
        EXPECT_NEAR(n.x, k == 0 ? 0.48f : -0.48f, 1e-5f) << k;
        EXPECT_NEAR(n.y, 0.36f, 1e-5f) << k;
    }
}

TEST_F(TangentImport, NoNormalMapNoTangents) {
    GltfFile file;
    Json j = mesh(file, kSquare, kSquareUvs, kSquareTriangles, std::vector<glm::vec4>(4, glm::vec4(1, 0, 0, 1)));
    j["materials"][0].erase("normalTexture");
    write("plain.glb", test::glb(j.dump(), file.bin()));
    const SceneDescription d = load(R"({"type": "mesh_file", "file": "plain.glb", "material": "from_file"})");
    EXPECT_TRUE(d.meshes[0].tangents.empty());
    EXPECT_TRUE(build_scene(d).texture_coordinates.empty());
}

TEST(TangentPlacement, AMirrorFlipsTheHandedness) {
    // Placed by x -> -x: the tangent +x becomes -x, and the bitangent, which the mirror leaves at
    // +y, is cross(N, T) w with N still +z: w must become -1.
    const glm::dmat3 mirror = glm::dmat3(glm::scale(glm::dmat4(1.0), glm::dvec3(-1.0, 1.0, 1.0)));
    EXPECT_EQ(placed_tangent(glm::vec4(1, 0, 0, 1), mirror), glm::vec4(-1, 0, 0, -1));
    EXPECT_EQ(placed_tangent(glm::vec4(1, 0, 0, 1), glm::dmat3(2.0)), glm::vec4(1, 0, 0, 1));
    EXPECT_EQ(placed_tangent(glm::vec4(1, 0, 0, 0), mirror), glm::vec4(1, 0, 0, 0));  // none stays none
}

// Instanced meshes' vertex tangents are in object space: the normal a hit gets agrees with the
// flattened scene's (tangents placed by placed_tangent) under the seven test placements, two
// of them mirroring; without the flip of w a mirrored placement's would lean the other way.
TEST(TangentPlacement, InstancesAgreeWithTheFlattenedScene) {
    const int rings = 4, segments = 2 * rings;
    SceneDescription d = test::instanced_scene(test::test_placements(), true, rings);
    TriangleMesh& part = d.prototypes[0].parts[0];
    for (std::size_t k = 0; k < part.vertices.size(); ++k) {
        part.uvs.push_back({float(k % segments) / float(segments), float(k / segments) / float(rings)});
        // Some tangent in the vertex's plane, each third vertex left-handed.
        const glm::vec3 t = glm::normalize(glm::cross(part.normals[k], glm::vec3(0.3f, 1.0f, 0.2f)));
        part.tangents.push_back(glm::vec4(t, k % 3 == 0 ? -1.0f : 1.0f));
    }
    d.textures.push_back(leaning());
    d.materials[1].normal_texture = 0;
    const Scene instanced = build_scene(d);
    const Scene flat = build_scene(test::flattened(d));
    SceneDescription unflipped_description = test::flattened(d);
    const std::size_t first_part = d.meshes.size();
    for (std::size_t k = 0; k < d.instances.size(); ++k) {
        const glm::dmat3 linear(d.instances[k].transform);
        const bool mirrored = glm::determinant(linear) < 0.0;
        std::vector<glm::vec4>& tangents = unflipped_description.meshes[first_part + k].tangents;
        for (std::size_t j = 0; j < tangents.size(); ++j) {
            const glm::vec4 placed = placed_tangent(part.tangents[j], linear);
            tangents[j] = glm::vec4(glm::vec3(placed), mirrored ? -placed.w : placed.w);
        }
    }
    const Scene unflipped = build_scene(unflipped_description);
    ASSERT_EQ(instanced.instances.triangle_count + instanced.triangles.size(), flat.triangles.size());
    const uint32_t per_instance = uint32_t(part.triangles.size());
    for (uint32_t k = 0; k < uint32_t(d.instances.size()); ++k) {
        const bool mirrored = glm::determinant(glm::dmat3(d.instances[k].transform)) < 0.0;
        int disagreeing = 0;
        for (uint32_t tri = 0; tri < per_instance; ++tri) {
            const uint32_t prim = instanced.instances.first_id + k * per_instance + tri;
            // The flattened copy of a mirrored triangle has vertices 1 and 2 swapped. Weights
            // 0.6, 0.15 and 0.25: no sum of them with signs is near 0 (where w's side could round
            // either way).
            const glm::vec3 a = mapped_normal(instanced, prim, 0.15f, 0.25f);
            const glm::vec3 b = mapped_normal(flat, prim, mirrored ? 0.25f : 0.15f, mirrored ? 0.15f : 0.25f);
            EXPECT_LT(glm::distance(a, b), 2e-3f) << "instance " << k << " triangle " << tri;
            const glm::vec3 c = mapped_normal(unflipped, prim, mirrored ? 0.25f : 0.15f, mirrored ? 0.15f : 0.25f);
            disagreeing += glm::distance(a, c) > 0.1f;
        }
        if (mirrored) EXPECT_GT(disagreeing, int(per_instance) / 2) << "instance " << k;
        else EXPECT_EQ(disagreeing, 0) << "instance " << k;
    }
}

}  // namespace
}  // namespace wt
