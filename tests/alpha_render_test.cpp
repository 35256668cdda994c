// Alpha-tested materials in the renderer (glTF alphaMode MASK and BLEND, core/scene/alpha_test.h,
// tested inside traversal by kernels/accel/alpha_filter.h): a cut-out card in front of an
// emitting wall shows the wall through its hole and the card elsewhere (camera rays); the shadow
// of a cut-out card has its hole lit (shadow rays, the any-hit query); alphaCutoff moves the
// edge; BLEND lets a fraction alpha of the camera rays through; OPAQUE ignores alpha. An alpha
// scene's image is the same bits for every thread count, schedule, integrator, ISA and node
// width, and a scene whose alpha test keeps every hit has the bits of the scene without one.

#include <cmath>
#include <memory>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "core/scene/alpha_test.h"
#include "kernels/accel/scene_bvh.h"
#include "kernels/isa/intersect_dispatch.h"
#include "render_helpers.h"
#include "test_scenes.h"
#include "texture_test_images.h"

namespace wt {
namespace {

using test::texture_of;

// A square of half-side `half` centred at `centre`, facing `up_axis` (+z or +y; -y with
// `facing_down`), its texture coordinates over [0, 1]^2 with v = 0 at the far edge.
TriangleMesh square(glm::vec3 centre, float half, uint32_t material, char axis = 'z', bool facing_down = false) {
    TriangleMesh m;
    if (axis == 'z') {
        m.vertices = {centre + glm::vec3(-half, -half, 0), centre + glm::vec3(half, -half, 0), centre + glm::vec3(half, half, 0),
                      centre + glm::vec3(-half, half, 0)};
    } else if (!facing_down) {
        m.vertices = {centre + glm::vec3(-half, 0, half), centre + glm::vec3(half, 0, half), centre + glm::vec3(half, 0, -half),
                      centre + glm::vec3(-half, 0, -half)};
    } else {
        m.vertices = {centre + glm::vec3(-half, 0, -half), centre + glm::vec3(half, 0, -half), centre + glm::vec3(half, 0, half),
                      centre + glm::vec3(-half, 0, half)};
    }
    m.triangles = {{0, 1, 2}, {0, 2, 3}};
    m.uvs = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};
    m.material = material;
    return m;
}

Material diffuse(glm::vec3 albedo, glm::vec3 emission = glm::vec3(0.0f)) {
    Material m;
    m.type = MaterialType::lambertian;
    m.albedo = albedo;
    m.emission = emission;
    return m;
}

// 8 x 8 texels, alpha 0 in columns and rows 3 and 4 (a square hole over the middle quarter of
// the card's side, u and v in [0.375, 0.625]; bilinearly alpha is exactly 0 for u, v in
// [0.4375, 0.5625]) and 1 elsewhere.
TextureImage holed_texture() {
    return texture_of(8, 8, [](int x, int y) {
        const bool hole = (x == 3 || x == 4) && (y == 3 || y == 4);
        return glm::vec4(1.0f, 1.0f, 1.0f, hole ? 0.0f : 1.0f);
    }, TextureWrap::clamp);
}

constexpr glm::vec3 kWall(1.0f, 0.25f, 0.125f);

// A black card (material 0) of half-side 2 at z = 0 in front of a wall (material 1) at z = -1
// emitting kWall, seen from z = 3: the card fills the 16 x 16 image, which spans x, y in about
// [-1.09, 1.09] on it; the hole of holed_texture() is x, y in [-0.5, 0.5], and pixels 7 and 8
// see only its exact-zero part. Nothing else lights the scene, so a pixel that sees the card is
// exactly 0 and one that sees the wall exactly kWall.
SceneDescription card_before_wall(AlphaMode mode, float factor, float cutoff, bool textured = true, int spp = 4) {
    SceneDescription d;
    Material card = diffuse(glm::vec3(0.0f));
    card.alpha_mode = mode, card.alpha_factor = factor, card.alpha_cutoff = cutoff;
    if (textured) {
        d.textures.push_back(holed_texture());
        card.alpha_texture = 0;
    }
    d.materials = {card, diffuse(glm::vec3(0.0f), kWall)};
    d.meshes = {square(glm::vec3(0.0f), 2.0f, 0), square(glm::vec3(0.0f, 0.0f, -1.0f), 3.0f, 1)};
    d.camera.eye = glm::vec3(0.0f, 0.0f, 3.0f);
    d.camera.look_at = glm::vec3(0.0f);
    d.camera.up = glm::vec3(0.0f, 1.0f, 0.0f);
    d.camera.fov_degrees = 40.0f;
    d.settings.width = d.settings.height = 16;
    d.settings.spp = uint32_t(spp);
    return d;
}

glm::dvec3 pixel(const Film& film, int x, int y) { return film.pixel_mean(uint32_t(y * film.width() + x)); }

TEST(AlphaRender, CameraRaysSeeTheWallThroughTheHole) {
    const Film masked = test::render_film(card_before_wall(AlphaMode::mask, 1.0f, 0.5f), Integrator::wavefront).film;
    const Film opaque = test::render_film(card_before_wall(AlphaMode::opaque, 1.0f, 0.5f), Integrator::wavefront).film;
    for (int y : {7, 8})
        for (int x : {7, 8}) {
            EXPECT_EQ(pixel(masked, x, y), glm::dvec3(kWall)) << x << "," << y;
            EXPECT_EQ(pixel(opaque, x, y), glm::dvec3(0.0)) << x << "," << y;
        }
    for (int y : {0, 15})
        for (int x : {0, 15}) {
            EXPECT_EQ(pixel(masked, x, y), glm::dvec3(0.0)) << x << "," << y;
            EXPECT_EQ(pixel(opaque, x, y), glm::dvec3(0.0)) << x << "," << y;
        }
}

// The card placed by an instance, turned a quarter about its normal (the hole stays in the
// middle): the alpha test reads the instanced mesh's material and object-space coordinates.
TEST(AlphaRender, InstancedCardShowsTheWallThroughTheHole) {
    for (const AlphaMode mode : {AlphaMode::mask, AlphaMode::opaque}) {
        SceneDescription d = card_before_wall(mode, 1.0f, 0.5f);
        MeshPrototype card;
        card.name = "card";
        card.parts.push_back(d.meshes[0]);
        d.meshes.erase(d.meshes.begin());
        d.prototypes.push_back(card);
        d.instances.push_back({0, glm::rotate(glm::dmat4(1.0), 0.5 * M_PI, glm::dvec3(0.0, 0.0, 1.0))});
        const test::RenderedFilm r = test::render_film(d, Integrator::wavefront);
        EXPECT_EQ(r.result.instance_count, 1u);
        const glm::dvec3 through = mode == AlphaMode::mask ? glm::dvec3(kWall) : glm::dvec3(0.0);
        for (int y : {7, 8})
            for (int x : {7, 8}) EXPECT_EQ(pixel(r.film, x, y), through) << x << "," << y;
        for (int y : {0, 15})
            for (int x : {0, 15}) EXPECT_EQ(pixel(r.film, x, y), glm::dvec3(0.0)) << x << "," << y;
    }
}

TEST(AlphaRender, OpaqueIgnoresAlphaEvenAtZero) {
    // glTF 2.0, 3.9.4: with OPAQUE "the alpha value is ignored"; a factor of 0 and the holed
    // texture still block. The same card as MASK lets every ray through.
    const Film opaque = test::render_film(card_before_wall(AlphaMode::opaque, 0.0f, 0.5f), Integrator::wavefront).film;
    const Film masked = test::render_film(card_before_wall(AlphaMode::mask, 0.0f, 0.5f), Integrator::wavefront).film;
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x) {
            EXPECT_EQ(pixel(opaque, x, y), glm::dvec3(0.0)) << x << "," << y;
            EXPECT_EQ(pixel(masked, x, y), glm::dvec3(kWall)) << x << "," << y;
        }
}

// Pixels of row 8 that see more wall than card.
int wall_pixels_in_row(const Film& film) {
    int n = 0;
    for (int x = 0; x < 16; ++x) n += pixel(film, x, 8).x > 0.5 * kWall.x;
    return n;
}

TEST(AlphaRender, CutoffMovesTheEdge) {
    // Alpha rising from 0 at the card's middle column to 1 at its edges (|u - 0.5| * 4 across
    // the visible part, clamped): the higher the cutoff, the wider the part cut out.
    SceneDescription d = card_before_wall(AlphaMode::mask, 1.0f, 0.5f);
    d.textures[0] = texture_of(64, 1, [](int x, int) {
        const float u = (float(x) + 0.5f) / 64.0f;
        return glm::vec4(1.0f, 1.0f, 1.0f, std::min(1.0f, std::fabs(u - 0.5f) * 4.0f));
    }, TextureWrap::clamp);
    std::vector<int> cut;
    for (float cutoff : {0.1f, 0.5f, 0.9f}) {
        d.materials[0].alpha_cutoff = cutoff;
        cut.push_back(wall_pixels_in_row(test::render_film(d, Integrator::wavefront).film));
    }
    EXPECT_GT(cut[0], 0);
    EXPECT_LT(cut[0], cut[1]);
    EXPECT_LT(cut[1], cut[2]);
    EXPECT_LT(cut[2], 16);
    // A cutoff of 0 keeps everything (alpha >= 0 always), one above 1 nothing.
    d.materials[0].alpha_cutoff = 0.0f;
    EXPECT_EQ(wall_pixels_in_row(test::render_film(d, Integrator::wavefront).film), 0);
    d.materials[0].alpha_cutoff = 1.5f;
    EXPECT_EQ(wall_pixels_in_row(test::render_film(d, Integrator::wavefront).film), 16);
}

TEST(AlphaRender, BlendLetsAlphaOfTheRaysThrough) {
    // Each camera ray sees the wall (kWall) with probability 1 - alpha, else the black card:
    // the image mean of red over N samples is (1 - alpha) kWall.x, with the binomial standard
    // error kWall.x sqrt(alpha (1 - alpha) / N); allowed 5 of them.
    const int spp = 32;
    for (float alpha : {0.5f, 0.25f}) {
        const Film film = test::render_film(card_before_wall(AlphaMode::blend, alpha, 0.5f, false, spp), Integrator::wavefront).film;
        double sum = 0.0;
        for (int y = 0; y < 16; ++y)
            for (int x = 0; x < 16; ++x) sum += pixel(film, x, y).x;
        const double mean = sum / 256.0, n = 256.0 * spp;
        const double expected = (1.0 - alpha) * kWall.x;
        const double sigma = kWall.x * std::sqrt(double(alpha) * (1.0 - alpha) / n);
        EXPECT_NEAR(mean, expected, 5.0 * sigma) << "alpha " << alpha;
    }
    // The ends are certain: alpha 1 always hits, alpha 0 never.
    const Film solid = test::render_film(card_before_wall(AlphaMode::blend, 1.0f, 0.5f, false), Integrator::wavefront).film;
    const Film clear = test::render_film(card_before_wall(AlphaMode::blend, 0.0f, 0.5f, false), Integrator::wavefront).film;
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x) {
            EXPECT_EQ(pixel(solid, x, y), glm::dvec3(0.0));
            EXPECT_EQ(pixel(clear, x, y), glm::dvec3(kWall));
        }
}

// A white floor at y = 0 under a black card at y = 2 (material 0, holed as card_before_wall's
// is: the hole is x, z in [-0.5, 0.5]) under a small light at y = 4 facing down, seen from
// y = 1.8 below the card (which the camera never sees): the floor's middle is lit through the
// hole, and pixel columns 0 and 15 see floor points (|x| > 1.6) whose every shadow ray crosses
// the card where alpha is 1. Light reaches the floor by the light samples' shadow rays alone
// (the card is black, and the light seen after a diffuse bounce is the light samples' part).
SceneDescription floor_under_card(AlphaMode mode, float factor = 1.0f, bool textured = true) {
    SceneDescription d;
    Material card = diffuse(glm::vec3(0.0f));
    card.alpha_mode = mode, card.alpha_factor = factor;
    if (textured) {
        d.textures.push_back(holed_texture());
        card.alpha_texture = 0;
    }
    d.materials = {card, diffuse(glm::vec3(0.8f)), diffuse(glm::vec3(0.0f), glm::vec3(400.0f))};
    d.meshes = {square(glm::vec3(0.0f, 2.0f, 0.0f), 2.0f, 0, 'y'), square(glm::vec3(0.0f), 4.0f, 1, 'y'),
                square(glm::vec3(0.0f, 4.0f, 0.0f), 0.1f, 2, 'y', true)};
    d.camera.eye = glm::vec3(0.0f, 1.8f, 0.0f);
    d.camera.look_at = glm::vec3(0.0f);
    d.camera.up = glm::vec3(0.0f, 0.0f, -1.0f);
    d.camera.fov_degrees = 90.0f;
    d.settings.width = d.settings.height = 16;
    d.settings.spp = 4;
    return d;
}

TEST(AlphaRender, ShadowRaysPassThroughTheHole) {
    const Film masked = test::render_film(floor_under_card(AlphaMode::mask), Integrator::wavefront).film;
    const Film opaque = test::render_film(floor_under_card(AlphaMode::opaque), Integrator::wavefront).film;
    for (int y : {7, 8})
        for (int x : {7, 8}) {
            EXPECT_GT(pixel(masked, x, y).x, 0.1) << x << "," << y;
            EXPECT_EQ(pixel(opaque, x, y), glm::dvec3(0.0)) << x << "," << y;
        }
    for (int y : {7, 8})
        for (int x : {0, 15}) EXPECT_EQ(pixel(masked, x, y), glm::dvec3(0.0)) << x << "," << y;
}

TEST(AlphaRender, BlendShadowLetsHalfTheLightThrough) {
    // The floor's middle under a BLEND card of alpha 0.5 without a hole receives half of what it
    // receives under a fully transparent one (alpha 0: every shadow ray passes, the same light
    // samples), within 5 standard errors of the ratio (per-pixel sample variances, delta method).
    SceneDescription half = floor_under_card(AlphaMode::blend, 0.5f, false), clear = floor_under_card(AlphaMode::blend, 0.0f, false);
    half.settings.spp = clear.settings.spp = 64;
    const Film h = test::render_film(half, Integrator::wavefront).film, c = test::render_film(clear, Integrator::wavefront).film;
    double sum_h = 0, sum_c = 0, var_h = 0, var_c = 0;
    for (int y = 4; y < 12; ++y)
        for (int x = 4; x < 12; ++x) {
            const uint32_t p = uint32_t(y * 16 + x);
            sum_h += h.pixel_mean(p).x, sum_c += c.pixel_mean(p).x;
            var_h += h.pixel_sample_variance(p).x / 64.0, var_c += c.pixel_sample_variance(p).x / 64.0;
        }
    ASSERT_GT(sum_c, 0.0);
    const double ratio = sum_h / sum_c;
    const double sigma = ratio * std::sqrt(var_h / (sum_h * sum_h) + var_c / (sum_c * sum_c));
    EXPECT_NEAR(ratio, 0.5, 5.0 * sigma);
    EXPECT_LT(5.0 * sigma, 0.1);  // the test can tell 0.5 from 0.4 and 0.6
}

TEST(AlphaRender, SameBitsForEveryScheduleIsaAndWidth) {
    for (const SceneDescription& d : {card_before_wall(AlphaMode::mask, 1.0f, 0.5f), floor_under_card(AlphaMode::mask),
                                      card_before_wall(AlphaMode::blend, 0.5f, 0.5f, false), floor_under_card(AlphaMode::blend, 0.5f, false)}) {
        const Film film = test::render_film(d, Integrator::wavefront).film;
        test::expect_same_film_for_any_schedule(d, film);
        for (Isa isa : kAllIsas) {
            if (!cpu_supports(isa)) continue;
            for (int width : {4, 8}) {
                EXPECT_TRUE(film == test::render_film(d, Integrator::wavefront, 1, 16, 2048, isa, Accel::bvh, width).film)
                    << isa_name(isa) << " width " << width;
                EXPECT_TRUE(film == test::render_film(d, Integrator::reference, 1, 16, 2048, isa, Accel::bvh, width).film)
                    << isa_name(isa) << " width " << width;
            }
        }
    }
}

TEST(AlphaRender, PassesAndSplitRendersAddToTheWholeRendersBits) {
    // BLEND's coins are functions of the rays alone: a render resumed into the same film, or
    // split into sample ranges and merged, is the whole render's bits.
    for (const SceneDescription& d : {card_before_wall(AlphaMode::blend, 0.5f, 0.5f, false, 11),
                                      floor_under_card(AlphaMode::blend, 0.5f, false)}) {
        const Scene scene = build_scene(d);
        const Film whole = test::render_film(d, Integrator::wavefront, 2).film;
        RenderOptions options;
        options.threads = 3;
        RenderSession session(scene, options);
        Film resumed = test::film_for(scene);
        session.render_samples(resumed, {0, 1});
        session.render_samples(resumed, {1, uint32_t(d.settings.spp)});
        EXPECT_TRUE(resumed == whole);
        Film first = test::film_for(scene), second = test::film_for(scene);
        session.render_samples(second, {2, uint32_t(d.settings.spp)});
        session.render_samples(first, {0, 2});
        EXPECT_FALSE(first == whole);
        first.add_film(second);
        EXPECT_TRUE(first == whole);
    }
}

TEST(AlphaRender, AlphaTestThatKeepsEveryHitHasTheOpaqueBits) {
    // The hexroom (walls as parallelograms, spheres, a tetrahedron) with every material MASK at
    // alpha 1: the alpha kernels (one ray at a time, every candidate asked) return the hits the
    // opaque room's kernels return, so the image is the same bits.
    for (Isa isa : {Isa::scalar, Isa::avx2}) {
        if (!cpu_supports(isa)) continue;
        const SceneDescription plain = test::hexroom(24, 16, 4);
        SceneDescription masked = plain;
        for (Material& m : masked.materials) m.alpha_mode = AlphaMode::mask;
        ASSERT_TRUE(build_scene(masked).has_alpha_materials);
        const Film expected = test::render_film(plain, Integrator::wavefront, 2, 16, 2048, isa).film;
        EXPECT_TRUE(expected == test::render_film(masked, Integrator::wavefront, 2, 16, 2048, isa).film) << isa_name(isa);
        EXPECT_TRUE(expected == test::render_film(masked, Integrator::reference, 2, 16, 2048, isa).film) << isa_name(isa);
    }
}

TEST(AlphaRender, OnlyAlphaScenesAskTheAlphaTest) {
    const Scene plain = build_scene(test::hexroom(8, 8, 1));
    EXPECT_FALSE(plain.has_alpha_materials);
    EXPECT_EQ(build_scene_bvh(plain, {}, nullptr).view.alpha_keeps, nullptr);
    const Scene masked = build_scene(card_before_wall(AlphaMode::mask, 1.0f, 0.5f));
    EXPECT_TRUE(masked.has_alpha_materials);
    EXPECT_NE(build_scene_bvh(masked, {}, nullptr).view.alpha_keeps, nullptr);
    // The flat list has no alpha test: a render that asks for it is refused by name.
    RenderOptions options;
    options.accel = Accel::brute;
    try {
        RenderSession session(masked, options);
        ADD_FAILURE() << "--accel brute accepted for an alpha-tested scene";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("alpha"), std::string::npos) << e.what();
    }
}

TEST(AlphaTest, DecidesAsTheMaterialSays) {
    const Scene scene = build_scene(card_before_wall(AlphaMode::mask, 1.0f, 0.5f));
    // Triangle 0 is (v0, v1, v2) of the card, whose coordinates at barycentrics (u, v) are
    // (u + v, 1 - v).
    EXPECT_FALSE(alpha_keeps_hit(&scene, 0, 0.0f, 0.5f, 0));  // texture (0.5, 0.5): the hole
    EXPECT_TRUE(alpha_keeps_hit(&scene, 0, 0.05f, 0.0f, 0));  // texture (0.05, 1): solid
    EXPECT_TRUE(alpha_keeps_hit(&scene, 2, 0.5f, 0.5f, 0));   // the wall, opaque
    // BLEND's coin is uniform: its mean over many keys is 1/2 within 5 standard errors.
    double sum = 0.0;
    const int n = 100000;
    for (int k = 0; k < n; ++k) sum += blend_coin(uint64_t(k) * 0x9E3779B97F4A7C15ull, 7);
    EXPECT_NEAR(sum / n, 0.5, 5.0 * std::sqrt(1.0 / 12.0 / n));
}

}  // namespace
}  // namespace wt
