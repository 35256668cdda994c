// Smooth-shaded meshes in the renderer: build_scene stores vertex normals only for scenes that
// have them and surface_at interpolates them; a flat scene renders the same bits whether or not
// the shading-normal code is present; the white furnace of a smooth-shaded closed mesh stays at
// Le / (1 - rho) for any vertex normals, however wrong; no light leaks through a closed
// smooth-shaded mesh; no NaN or Inf with adversarial normals on every material; both
// integrators give the same bits on smooth scenes.

#include <cmath>
#include <random>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "render_helpers.h"
#include "test_scenes.h"
#include "white_furnace_check.h"

namespace wt {
namespace {

using test::icosphere;

// Vertex normals from the kind test wants; the renderer must cope with all of them.
enum class Normals { none, outward, inward, random, tangent };

std::vector<glm::vec3> vertex_normals(const TriangleMesh& m, Normals kind, uint32_t seed) {
    std::mt19937 rng(seed);
    std::normal_distribution<float> gauss;
    std::vector<glm::vec3> normals;
    if (kind == Normals::none) return normals;
    for (const glm::vec3& v : m.vertices) {
        const glm::vec3 radial = glm::normalize(v);
        switch (kind) {
            case Normals::none: break;
            case Normals::outward: normals.push_back(radial); break;
            case Normals::inward: normals.push_back(-radial); break;
            case Normals::random: normals.push_back(glm::normalize(glm::vec3(gauss(rng), gauss(rng), gauss(rng)))); break;
            case Normals::tangent: {
                const glm::vec3 axis = std::fabs(radial.z) < 0.9f ? glm::vec3(0, 0, 1) : glm::vec3(1, 0, 0);
                normals.push_back(glm::normalize(glm::cross(radial, axis)));
                break;
            }
        }
    }
    return normals;
}

// The mesh scaled by r, wound to face its centre (so a light on it shines inwards).
TriangleMesh facing_inwards(TriangleMesh m, float r) {
    for (glm::vec3& v : m.vertices) v *= r;
    for (auto& tri : m.triangles) std::swap(tri[1], tri[2]);
    return m;
}

// The white furnace inside a smooth-shaded icosphere of radius 2 (320 faces), seen from its
// centre: every face has albedo rho and emits Le towards the centre.
SceneDescription smooth_furnace(float rho, float le, MaterialType type, float sigma, Normals kind) {
    SceneDescription d = test::furnace_cube(rho, le, type, sigma);
    TriangleMesh sphere = facing_inwards(icosphere(2), 2.0f);
    sphere.normals = vertex_normals(sphere, kind, 7);
    sphere.material = 0;
    d.meshes = {sphere};
    d.settings.accuracy.triangles = TriangleTest::watertight;
    return d;
}

TEST(ShadingNormalStorage, OnlyScenesWithVertexNormalsStoreThem) {
    const Scene flat = build_scene(test::hexroom(4, 4, 1));
    EXPECT_TRUE(flat.shading_normals.empty());
    EXPECT_EQ(flat.shading_normals.size(), 0u);

    SceneDescription d = test::hexroom(4, 4, 1);
    TriangleMesh ball = icosphere(1);
    ball.normals = vertex_normals(ball, Normals::outward, 1);
    d.meshes.push_back(ball);
    const Scene smooth = build_scene(d);
    EXPECT_EQ(smooth.shading_normals.size(), smooth.triangles.vertex_count());  // flat vertices marked, not skipped
    EXPECT_EQ(smooth.shading_normals.smooth_count(), ball.vertices.size());
    EXPECT_EQ(smooth.triangles.parallelogram_count, flat.triangles.parallelogram_count);
}

// The table stores each mesh's vertex normals once and indexes them: every triangle of a second
// smooth mesh, after a flat one, still reads its own mesh's normals, not the first mesh's.
TEST(ShadingNormalStorage, EachTriangleReadsItsOwnMeshsVertexNormalsOnce) {
    SceneDescription d = test::furnace_cube(0.5f, 1.0f);
    const std::size_t before = d.meshes.size();
    TriangleMesh outward = icosphere(1), flat = icosphere(1), random = icosphere(2);
    outward.normals = vertex_normals(outward, Normals::outward, 1);
    random.normals = vertex_normals(random, Normals::random, 3);
    d.meshes.push_back(outward);
    d.meshes.push_back(flat);
    d.meshes.push_back(random);
    const Scene scene = build_scene(d);
    ASSERT_GT(before, 0u);
    // The cube's walls come first (as parallelograms or triangles), then the three meshes.
    const std::size_t added = outward.triangles.size() + flat.triangles.size() + random.triangles.size();
    ASSERT_EQ(scene.shading_normals.size(), scene.triangles.vertex_count());
    std::size_t i = scene.triangles.size() - added;
    glm::vec3 n[3];
    for (std::size_t k = 0; k < i; ++k) EXPECT_FALSE(scene.shading_normals.vertex_normals(scene.triangles, k, n)) << "triangle " << k;
    for (const TriangleMesh* mesh : {&outward, &flat, &random}) {
        for (const auto& tri : mesh->triangles) {
            const bool smooth = !mesh->normals.empty();
            ASSERT_EQ(scene.shading_normals.vertex_normals(scene.triangles, i, n), smooth) << "triangle " << i;
            if (smooth) {
                for (int c = 0; c < 3; ++c) EXPECT_EQ(n[c], mesh->normals[tri[c]]) << "triangle " << i << " corner " << c;
            }
            ++i;
        }
    }
    // One normal (or flat marker) per vertex, and nothing per triangle: the triangles' own
    // vertex indices find them.
    EXPECT_EQ(scene.shading_normals.bytes(), scene.triangles.vertex_count() * sizeof(glm::vec3));
    EXPECT_EQ(scene.shading_normals.smooth_count(), outward.vertices.size() + random.vertices.size());
}

TEST(ShadingNormalStorage, AQuadWithVertexNormalsStaysTwoTriangles) {
    SceneDescription d = test::furnace_cube(0.5f, 1.0f);
    TriangleMesh quad;
    quad.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    quad.triangles = {{0, 1, 2}, {0, 2, 3}};
    quad.parallelogram = true;
    d.meshes = {quad};
    EXPECT_EQ(build_scene(d).triangles.parallelogram_count, 1u);
    d.meshes[0].normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
    const Scene smooth = build_scene(d);
    EXPECT_EQ(smooth.triangles.parallelogram_count, 0u);
    EXPECT_EQ(smooth.triangles.size(), 2u);
}

TEST(ShadingNormalStorage, ANormalCountOtherThanTheVertexCountIsRefused) {
    SceneDescription d = test::furnace_cube(0.5f, 1.0f);
    d.meshes[0].normals = {{0, 0, 1}};
    EXPECT_THROW(build_scene(d), std::invalid_argument);
}

TEST(SurfaceAt, InterpolatesTheVertexNormalsAndFallsBackWhereTheyCancel) {
    SceneDescription d = test::furnace_cube(0.5f, 1.0f);
    TriangleMesh tri;
    tri.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    tri.triangles = {{0, 1, 2}};
    const glm::vec3 n1 = glm::normalize(glm::vec3(0.3f, 0, 1)), n2 = glm::normalize(glm::vec3(0, -0.4f, 1));
    tri.normals = {{0, 0, -1}, n1, n2};
    d.meshes = {tri};
    const Scene scene = build_scene(d);
    const Ray ray{{0.25f, 0.25f, 1.0f}, {0, 0, -1}};
    auto at = [&](float u, float v) { return surface_at(scene, ray, Hit{1.0f, 0, u, v}); };

    EXPECT_EQ(at(0.25f, 0.25f).normal, glm::vec3(0, 0, 1));  // the geometric normal is untouched
    EXPECT_NEAR(glm::length(at(1.0f, 0.0f).shading_normal - n1), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::length(at(0.0f, 1.0f).shading_normal - n2), 0.0f, 1e-6f);
    const glm::vec3 middle = at(0.3f, 0.3f).shading_normal;
    const glm::vec3 expected = glm::normalize(0.4f * glm::vec3(0, 0, -1) + 0.3f * n1 + 0.3f * n2);
    EXPECT_NEAR(glm::length(middle - expected), 0.0f, 1e-6f);
    EXPECT_TRUE(at(0.3f, 0.3f).smooth);
    // Halfway between (0, 0, -1) and n1 ~ (0, 0, 1) the normals nearly cancel; exactly between
    // opposite normals they do, and the geometric normal is used instead of 0/0.
    d.meshes[0].normals = {{0, 0, -1}, {0, 0, 1}, {0, 0, 1}};
    const Scene cancelling = build_scene(d);
    const SurfacePoint s = surface_at(cancelling, ray, Hit{1.0f, 0, 0.5f, 0.0f});
    EXPECT_EQ(s.shading_normal, s.normal);
    EXPECT_FALSE(s.smooth);
}

// A smooth mesh no ray can reach (a tiny triangle far outside the closed room) builds the
// shading-normal table; the rest of the scene must render the same bits as without it.
TEST(ShadingNormals, AFlatSceneRendersTheSameBitsWithTheSmoothCodePresent) {
    SceneDescription flat = test::hexroom(20, 20, 8, 9);
    // The automatic photon radius follows the scene's bounds, which the far triangle widens.
    flat.settings.estimator.photon_radius = 0.05f;
    SceneDescription with_table = flat;
    TriangleMesh far_away;
    far_away.vertices = {{100, 100, 100}, {100.001f, 100, 100}, {100, 100.001f, 100}};
    far_away.triangles = {{0, 1, 2}};
    far_away.normals = {{0, 0, 1}, {0, 1, 0}, {1, 0, 0}};
    with_table.meshes.push_back(far_away);
    ASSERT_FALSE(build_scene(with_table).shading_normals.empty());
    for (Integrator integrator : {Integrator::wavefront, Integrator::reference}) {
        const test::RenderedFilm a = test::render_film(flat, integrator);
        const test::RenderedFilm b = test::render_film(with_table, integrator);
        EXPECT_TRUE(test::films_bit_identical(a.film, b.film));
        EXPECT_EQ(a.result.counts.total_rays(), b.result.counts.total_rays());
    }
}

struct SmoothFurnaceCase {
    const char* name;
    Integrator integrator;
    Normals normals;
    MaterialType type;
    float rho;
};

class SmoothFurnace : public ::testing::TestWithParam<SmoothFurnaceCase> {};

// K integrates to rho for any shading normal, and BSDF sampling and light sampling both use
// it, so the furnace holds for normals that are right (outward or inward: the renderer turns
// them to the ray's side), random, or tangent to the surface.
TEST_P(SmoothFurnace, EveryPixelConvergesToLeOverOneMinusRho) {
    const SmoothFurnaceCase c = GetParam();
    const float le = 1.0f;
    const SceneDescription d = smooth_furnace(c.rho, le, c.type, 0.0f, c.normals);
    const test::RenderedFilm r = test::render_film(d, c.integrator);
    test::expect_white_furnace(r, d, le / (1.0 - c.rho));
}

INSTANTIATE_TEST_SUITE_P(
    NormalsAndIntegrators, SmoothFurnace,
    ::testing::Values(
        SmoothFurnaceCase{"wavefront_flat_lambert_half", Integrator::wavefront, Normals::none, MaterialType::lambertian, 0.5f},
        SmoothFurnaceCase{"wavefront_outward_lambert_half", Integrator::wavefront, Normals::outward, MaterialType::lambertian, 0.5f},
        SmoothFurnaceCase{"reference_inward_lambert_bright", Integrator::reference, Normals::inward, MaterialType::lambertian, 0.8f},
        SmoothFurnaceCase{"wavefront_random_lambert_half", Integrator::wavefront, Normals::random, MaterialType::lambertian, 0.5f},
        SmoothFurnaceCase{"reference_random_lambert_bright", Integrator::reference, Normals::random, MaterialType::lambertian, 0.8f},
        SmoothFurnaceCase{"wavefront_tangent_lambert_half", Integrator::wavefront, Normals::tangent, MaterialType::lambertian, 0.5f},
        SmoothFurnaceCase{"wavefront_random_oren_nayar_sigma_0", Integrator::wavefront, Normals::random, MaterialType::oren_nayar, 0.5f}),
    [](const auto& info) { return std::string(info.param.name); });

// A rough surface loses energy, never gains it, about random shading normals too.
TEST(SmoothFurnace, OrenNayarWithRoughnessStaysBelowTheLambertianAnswer) {
    const SceneDescription d = smooth_furnace(0.8f, 1.0f, MaterialType::oren_nayar, 0.9f, Normals::random);
    const test::RenderedFilm r = test::render_film(d, Integrator::wavefront);
    double mean = 0.0, variance = 0.0;
    const int pixels = d.settings.width * d.settings.height;
    for (uint32_t p = 0; p < uint32_t(pixels); ++p) mean += r.film.pixel_mean(p).y, variance += r.film.pixel_sample_variance(p).y;
    mean /= pixels;
    const double standard_error = std::sqrt(variance / pixels / (double(d.settings.spp) * pixels));
    EXPECT_LT(mean, 1.0 / (1.0 - 0.8) + 4.5 * standard_error);
    EXPECT_GT(mean, 2.0);  // and not black
    EXPECT_EQ(r.result.counts.nonfinite_samples, 0u);
}

// Camera inside a closed smooth-shaded sphere (diffuse and mirror faces, random vertex normals)
// that emits nothing, inside a lit furnace box: every path that stays inside sees no light, so
// every pixel must be exactly 0. A direction sampled about the shading normal that went on
// below the geometric surface would pass through the wall and find the light. (The watertight
// test, so that no ray slips between the sphere's triangles on its own.)
TEST(ShadingNormals, NoLightLeaksIntoAClosedSmoothMesh) {
    SceneDescription d = test::furnace_cube(0.5f, 1.0f);
    for (glm::vec3& v : d.meshes[0].vertices) v *= 3.0f;
    d.settings.accuracy.triangles = TriangleTest::watertight;
    Material white = test::furnace_cube(0.8f, 0.0f).materials[0], mirror;
    white.emission = glm::vec3(0.0f);
    mirror.type = MaterialType::mirror;
    d.materials.push_back(white), d.materials.push_back(mirror);
    TriangleMesh sphere = facing_inwards(icosphere(2), 1.0f);
    sphere.normals = vertex_normals(sphere, Normals::random, 11);
    TriangleMesh diffuse_part = sphere, mirror_part = sphere;  // the same vertices, alternate faces
    diffuse_part.triangles.clear(), mirror_part.triangles.clear();
    for (std::size_t i = 0; i < sphere.triangles.size(); ++i) (i % 3 ? diffuse_part : mirror_part).triangles.push_back(sphere.triangles[i]);
    diffuse_part.material = 1, mirror_part.material = 2;
    d.meshes.push_back(diffuse_part), d.meshes.push_back(mirror_part);
    d.settings.spp = 64;
    for (Integrator integrator : {Integrator::wavefront, Integrator::reference}) {
        const test::RenderedFilm r = test::render_film(d, integrator);
        int lit = 0;
        for (uint32_t p = 0; p < uint32_t(d.settings.width * d.settings.height); ++p) lit += r.film.pixel_sum(p) != glm::dvec3(0.0);
        EXPECT_EQ(lit, 0) << "pixels that saw light from outside the sphere";
        EXPECT_GT(r.result.counts.bounce_rays, r.result.counts.camera_rays);  // paths did bounce inside
        EXPECT_GT(r.result.counts.shadow_rays, 0u);
        EXPECT_EQ(r.result.counts.nonfinite_samples, 0u);
    }
}

// The hexroom with smooth meshes of every material whose normals are adversarial (random,
// tangent, opposite to the geometry, cancelling along lines), seen from the usual camera and
// from a camera 1 mm above a smooth floor, where most rays graze it. No sample may be NaN or
// infinite, and both integrators must give the same bits.
TEST(ShadingNormals, AdversarialNormalsOnEveryMaterialGiveNoNanAndTheSameBitsOnBothIntegrators) {
    SceneDescription d = test::hexroom(24, 24, 16, 13);
    auto material = [&](const char* name) {
        for (uint32_t i = 0; i < d.materials.size(); ++i)
            if (d.materials[i].name == name) return i;
        ADD_FAILURE() << name;
        return 0u;
    };
    struct Ball {
        const char* material;
        Normals normals;
        glm::vec3 center;
        float radius;
    };
    for (const Ball& b : {Ball{"glass", Normals::random, {4, 3, -3.5f}, 1.2f}, Ball{"mirror", Normals::tangent, {3, -3, -1}, 1.0f},
                          Ball{"rough", Normals::inward, {7, 0, 1}, 1.0f}, Ball{"white", Normals::random, {2, 0, 2.5f}, 0.8f},
                          Ball{"light", Normals::random, {8, 4, 3}, 0.5f}}) {
        TriangleMesh m = icosphere(1);
        m.normals = vertex_normals(m, b.normals, 17);
        for (glm::vec3& v : m.vertices) v = b.center + b.radius * v;
        m.material = material(b.material);
        d.meshes.push_back(m);
    }
    // The floor as a smooth mesh under the room's own floor, normals alternating up and down so
    // they cancel along lines across it, and one tilted to the horizon.
    TriangleMesh floor;
    floor.vertices = {{-2, -5, -4.9f}, {12, -5, -4.9f}, {12, 5, -4.9f}, {-2, 5, -4.9f}};
    floor.triangles = {{0, 1, 2}, {0, 2, 3}};
    floor.normals = {{0, 0, 1}, {0, 0, -1}, {0, 0, 1}, glm::normalize(glm::vec3(1, 0, 1e-3f))};
    floor.material = material("white");
    d.meshes.push_back(floor);

    SceneDescription grazing = d;
    grazing.camera.eye = glm::vec3(0, 0, -4.899f);
    grazing.camera.look_at = glm::vec3(10, 0, -4.899f);
    for (const SceneDescription* s : {&d, &grazing}) {
        const test::RenderedFilm wave = test::render_film(*s, Integrator::wavefront);
        const test::RenderedFilm ref = test::render_film(*s, Integrator::reference);
        EXPECT_EQ(wave.result.counts.nonfinite_samples, 0u);
        EXPECT_EQ(ref.result.counts.nonfinite_samples, 0u);
        EXPECT_TRUE(test::films_bit_identical(wave.film, ref.film));
        double total = 0.0;
        for (uint32_t p = 0; p < uint32_t(s->settings.width * s->settings.height); ++p) {
            EXPECT_EQ(wave.film.pixel_count(p), uint32_t(s->settings.spp));
            total += wave.film.pixel_mean(p).y;
        }
        EXPECT_TRUE(std::isfinite(total) && total > 0.0);
    }
}

}  // namespace
}  // namespace wt
