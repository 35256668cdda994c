// Light selection among the emissive triangles (core/lights/emitter_selection.h, light_tree.h):
// probabilities that sum to one, the tree's pdf query against the frequency of its picks
// (chi-square), the tree against power selection where orientation and distance do not matter,
// and the sample's pdf equal, bit for bit, to the pdf a BSDF-sampled ray would ask for.

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "core/checkpoint/checkpoint_settings.h"
#include "core/lights/emitter_selection.h"
#include "core/lights/light_tree.h"
#include "core/sampling/rng.h"
#include "core/scene/scene.h"
#include "core/scene_file/scene_loader.h"
#include "many_lights_scene.h"
#include "statistics.h"

namespace wt {
namespace {

constexpr double kAlpha = 1e-4;  // false-alarm probability of each goodness-of-fit test

float uniform(uint64_t key, uint32_t i, uint32_t d) { return random_float(key, i, d); }

// n small triangles scattered in a 10-unit box, facing every way, of power spread over three decades.
std::vector<LightBounds> scattered_emitters(int n, uint64_t key) {
    std::vector<LightBounds> e(std::size_t(n), LightBounds{});
    for (int k = 0; k < n; ++k) {
        const uint32_t i = uint32_t(k);
        const glm::vec3 c(10.0f * uniform(key, i, 0), 10.0f * uniform(key, i, 1), 10.0f * uniform(key, i, 2));
        const float size = 0.05f + 0.2f * uniform(key, i, 3);
        e[std::size_t(k)].lo = c, e[std::size_t(k)].hi = c + glm::vec3(size);
        const float z = 2.0f * uniform(key, i, 4) - 1.0f, phi = 6.2831853f * uniform(key, i, 5);
        const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
        e[std::size_t(k)].axis = glm::vec3(r * std::cos(phi), r * std::sin(phi), z);
        e[std::size_t(k)].cos_theta_o = 1.0f;
        e[std::size_t(k)].power = std::pow(10.0f, 3.0f * uniform(key, i, 6));
    }
    return e;
}

const glm::vec3 kNormal = glm::normalize(glm::vec3(1.0f, 2.0f, 3.0f));  // of the surface at the shading points
const glm::vec3 kShadingPoints[] = {{5.0f, 5.0f, 5.0f}, {-3.0f, 2.0f, 1.0f}, {9.5f, 0.5f, 9.9f}, {50.0f, -20.0f, 4.0f}};

TEST(LightTree, IsConsistentAndDeterministic) {
    const std::vector<LightBounds> emitters = scattered_emitters(700, 11);
    const LightTree a(emitters), b(emitters);
    EXPECT_TRUE(a.is_consistent());
    EXPECT_EQ(a.size(), 700u);
    EXPECT_EQ(a.node_count(), 2u * 700u - 1u);
    EXPECT_LT(a.depth(), 40);
    for (const glm::vec3& p : kShadingPoints)
        for (uint32_t k = 0; k < 700; ++k) ASSERT_EQ(a.probability(p, kNormal, k), b.probability(p, kNormal, k));
}

// Where every emitter faces the point, the probabilities sum to one. Elsewhere the descent can
// reach a node neither of whose children faces the point (each child's cone is narrower than
// their union's): that sample is lost, which wastes it but biases nothing, as no emitter there
// could light the point; the sum is then what pick() succeeds with.
TEST(LightTree, ProbabilitiesSumToOneFromEveryPoint) {
    std::vector<LightBounds> emitters = scattered_emitters(500, 12);
    for (LightBounds& e : emitters) e.axis = glm::normalize(glm::vec3(0.5f * e.axis.x, 0.5f * e.axis.y, 1.0f));  // within 27 degrees of +z
    const LightTree tree(emitters);
    for (const glm::vec3& p : {glm::vec3(5.0f, 5.0f, 40.0f), glm::vec3(-3.0f, 2.0f, 60.0f), glm::vec3(9.5f, 0.5f, 35.0f)}) {
        double sum = 0.0;
        for (uint32_t k = 0; k < emitters.size(); ++k) sum += double(tree.probability(p, glm::vec3(0.0f, 0.0f, 1.0f), k));
        EXPECT_NEAR(sum, 1.0, 1e-5) << "from " << p.x << " " << p.y << " " << p.z;
    }
    const LightTree any_way(scattered_emitters(500, 12));
    for (const glm::vec3& p : kShadingPoints) {
        double sum = 0.0;
        for (uint32_t k = 0; k < emitters.size(); ++k) sum += double(any_way.probability(p, kNormal, k));
        EXPECT_LE(sum, 1.0 + 1e-5);
        EXPECT_GT(sum, 0.5);
    }
}

// Picks from a point follow probability() (Pearson's chi-square over the emitters and the lost
// samples), and each pick returns exactly the probability the query gives its emitter.
TEST(LightTree, PicksFollowTheProbabilityQuery) {
    const std::vector<LightBounds> emitters = scattered_emitters(300, 13);
    const LightTree tree(emitters);
    for (const glm::vec3& p : kShadingPoints) {
        const int n = 400000;
        std::vector<double> observed(emitters.size() + 1, 0.0), expected(emitters.size() + 1, 0.0);
        for (int s = 0; s < n; ++s) {
            LightTree::Pick pick;
            if (!tree.pick(p, kNormal, uniform(21, uint32_t(s), 0), pick)) {
                observed.back() += 1.0;
                continue;
            }
            ASSERT_EQ(pick.probability, tree.probability(p, kNormal, pick.emitter));
            observed[pick.emitter] += 1.0;
        }
        double sum = 0.0;
        for (uint32_t k = 0; k < emitters.size(); ++k) {
            expected[k] = double(n) * double(tree.probability(p, kNormal, k));
            sum += double(tree.probability(p, kNormal, k));
        }
        expected.back() = double(n) * std::max(0.0, 1.0 - sum);
        EXPECT_GT(test::chi_square_test(observed, expected).p_value, kAlpha) << "from " << p.x << " " << p.y << " " << p.z;
    }
}

// From far away, with every emitter facing the point, distance and orientation hardly differ:
// the tree's probabilities are the power shares.
TEST(LightTree, AgreesWithPowerWhereOrientationAndDistanceDoNotMatter) {
    std::vector<LightBounds> emitters(6, LightBounds{});
    const float power[6] = {1.0f, 2.0f, 5.0f, 0.5f, 8.0f, 3.5f};
    float total = 0.0f;
    for (int k = 0; k < 6; ++k) {
        const glm::vec3 c(0.3f * float(k % 3), 0.3f * float(k / 3), 0.0f);
        emitters[std::size_t(k)].lo = c, emitters[std::size_t(k)].hi = c + glm::vec3(0.1f, 0.1f, 0.0f);
        emitters[std::size_t(k)].axis = glm::vec3(0.0f, 0.0f, 1.0f);
        emitters[std::size_t(k)].power = power[k];
        total += power[k];
    }
    const LightTree tree(emitters);
    const glm::vec3 far(0.3f, 0.15f, 1000.0f);
    for (uint32_t k = 0; k < 6; ++k)
        EXPECT_NEAR(tree.probability(far, glm::vec3(0.0f, 0.0f, -1.0f), k), power[k] / total, 1e-3f) << "emitter " << k;
}

// An emitter the point is behind gets nothing; the others share everything.
TEST(LightTree, NeverPicksAnEmitterThePointIsBehind) {
    std::vector<LightBounds> emitters(2, LightBounds{});
    emitters[0].lo = glm::vec3(0.0f), emitters[0].hi = glm::vec3(0.1f, 0.1f, 0.0f), emitters[0].axis = {0, 0, 1};
    emitters[1].lo = glm::vec3(1.0f, 0.0f, 0.0f), emitters[1].hi = glm::vec3(1.1f, 0.1f, 0.0f), emitters[1].axis = {0, 0, -1};
    emitters[0].power = emitters[1].power = 1.0f;
    const LightTree tree(emitters);
    const glm::vec3 above(0.5f, 0.0f, 2.0f);
    EXPECT_EQ(tree.probability(above, glm::vec3(0.0f, 0.0f, 1.0f), 0), 1.0f);
    EXPECT_EQ(tree.probability(above, glm::vec3(0.0f, 0.0f, 1.0f), 1), 0.0f);
}

// The receiver's cosine: an emitter in the plane of the point's surface (a lamp on the same
// wall) faces the point but cannot light it. Its bound is the sine of the half-angle its box's
// bounding sphere subtends (conservative: never zero), so it gets a small share of what a
// receiver turned towards it would give it.
TEST(LightTree, NeverPicksAnEmitterInTheReceiversTangentPlane) {
    std::vector<LightBounds> emitters(2, LightBounds{});
    // Emitter 0 on the wall x = 0, facing into the room; emitter 1 off the wall, facing it.
    emitters[0].lo = glm::vec3(0.0f), emitters[0].hi = glm::vec3(0.0f, 0.1f, 0.1f), emitters[0].axis = {1, 0, 0};
    emitters[1].lo = glm::vec3(0.5f, 0.0f, 2.0f), emitters[1].hi = glm::vec3(0.5f, 0.1f, 2.1f), emitters[1].axis = {-1, 0, 0};
    emitters[0].power = emitters[1].power = 1.0f;
    const LightTree tree(emitters);
    const glm::vec3 on_wall(0.0f, 3.0f, 0.05f), wall_normal(1.0f, 0.0f, 0.0f);
    const float in_plane = tree.probability(on_wall, wall_normal, 0);
    const float facing = tree.probability(on_wall, glm::normalize(-on_wall), 0);  // a receiver turned towards it
    EXPECT_GT(in_plane, 0.0f);
    EXPECT_LT(in_plane, 0.25f * facing);
}

// The scene's selection: power shares of pi A L, and from any point the pdf a light sample
// carries equals, bit for bit, what emission_added asks for the triangle it landed on.
TEST(EmitterSelection, PowerSharesAndSamplePdfsMatchTheQuery) {
    for (LightSelection how : {LightSelection::power, LightSelection::bvh}) {
        SCOPED_TRACE(name_of(how));
        const Scene scene = build_scene(test::many_lights_room(12, LightSampling::nee, how));
        const EmitterSelection& s = scene.emitter_selection;
        ASSERT_FALSE(s.empty());
        ASSERT_EQ(scene.lights.size(), 144u);
        // Points on the floor, a wall and the metal block's top, with their surfaces' normals.
        const std::pair<glm::vec3, glm::vec3> points[] = {{{0.0f, 0.0f, 0.01f}, {0.0f, 0.0f, 1.0f}},
                                                          {{1.99f, -1.5f, 1.0f}, {-1.0f, 0.0f, 0.0f}},
                                                          {{0.7f, 0.7f, 0.61f}, {0.0f, 0.0f, 1.0f}}};
        for (const auto& [p, n] : points) {
            double sum = 0.0;
            for (uint32_t k = 0; k < scene.lights.size(); ++k) sum += double(s.probability(p, n, k));
            EXPECT_NEAR(sum, 1.0, 1e-5);
            for (uint32_t j = 0; j < 2000; ++j) {
                LightSample light;
                if (!s.sample(scene.lights, p, n, uniform(5, j, 0), uniform(5, j, 1), uniform(5, j, 2), light)) continue;
                // The triangle the point lies on: the emitter whose plane and box hold it.
                bool found = false;
                for (uint32_t k = 0; k < scene.lights.size() && !found; ++k) {
                    const uint32_t t = scene.lights.triangle_of(k);
                    const glm::vec3 v0 = scene.triangles.vertex0(t);
                    const glm::vec3 lo = glm::min(v0, glm::min(v0 + scene.triangles.edge1(t), v0 + scene.triangles.edge2(t)));
                    const glm::vec3 hi = glm::max(v0, glm::max(v0 + scene.triangles.edge1(t), v0 + scene.triangles.edge2(t)));
                    if (glm::all(glm::lessThanEqual(lo - 1e-5f, light.position)) &&
                        glm::all(glm::lessThanEqual(light.position, hi + 1e-5f)) &&
                        std::fabs(glm::dot(light.position - v0, scene.triangles.normal(t))) < 1e-5f) {
                        found = true;
                        EXPECT_EQ(light.pdf_area, s.pdf_area(p, n, t));
                    }
                }
                EXPECT_TRUE(found);
            }
        }
        if (how == LightSelection::power) {
            // Shares of area x luminance (the tilted triangles are larger).
            std::vector<double> power(scene.lights.size());
            double total = 0.0;
            for (uint32_t k = 0; k < scene.lights.size(); ++k) {
                const uint32_t t = scene.lights.triangle_of(k);
                const double area = 0.5 * double(glm::length(glm::cross(scene.triangles.edge1(t), scene.triangles.edge2(t))));
                power[k] = area * luminance(scene.materials[scene.triangles.material[t]].emission);
                total += power[k];
            }
            for (uint32_t k = 0; k < scene.lights.size(); ++k)
                EXPECT_NEAR(s.probability(glm::vec3(0.0f), glm::vec3(0.0f, 0.0f, 1.0f), k), power[k] / total, 1e-6 + 1e-5 * power[k] / total);
        }
    }
}

// The default: power where a scene has 16 emitters or more of different radiance; area (nothing
// built, today's loop and bits) with fewer, or when they all emit alike (power is area then).
TEST(EmitterSelection, AutomaticIsPowerForManyEmittersOfDifferentRadianceElseArea) {
    const auto chosen = [](const SceneDescription& d) {
        const Scene scene = build_scene(d);
        return scene.emitter_selection.empty() ? LightSelection::area : scene.emitter_selection.how();
    };
    EXPECT_EQ(chosen(test::many_lights_room(4, LightSampling::nee, LightSelection::automatic)), LightSelection::power);
    EXPECT_EQ(chosen(test::many_lights_room(3, LightSampling::nee, LightSelection::automatic)), LightSelection::area);  // 9
    SceneDescription alike = test::many_lights_room(8, LightSampling::nee, LightSelection::automatic);
    for (Material& m : alike.materials)
        if (m.is_emissive()) m.emission = glm::vec3(3.0f);
    EXPECT_EQ(chosen(alike), LightSelection::area);
    EXPECT_EQ(chosen(test::many_lights_room(8, LightSampling::nee, LightSelection::area)), LightSelection::area);
    EXPECT_EQ(chosen(test::many_lights_room(8, LightSampling::nee, LightSelection::bvh)), LightSelection::bvh);
}

// Only what a scene requires: with "area", or with one emitter, nothing is built and the
// integrators keep the area lights' loop.
TEST(EmitterSelection, NothingIsBuiltForAreaOrForOneEmitter) {
    const Scene area = build_scene(test::many_lights_room(4, LightSampling::nee, LightSelection::area));
    EXPECT_TRUE(area.emitter_selection.empty());
    EXPECT_TRUE(area.listed_lights.empty());
    SceneDescription one = test::many_lights_room(1, LightSampling::nee, LightSelection::bvh);
    const Scene single = build_scene(one);
    EXPECT_EQ(single.lights.size(), 1u);
    EXPECT_TRUE(single.emitter_selection.empty());
    EXPECT_TRUE(single.listed_lights.empty());
    const Scene tree = build_scene(test::many_lights_room(4, LightSampling::nee, LightSelection::bvh));
    EXPECT_FALSE(tree.emitter_selection.empty());
    EXPECT_FALSE(tree.listed_lights.empty());
    EXPECT_EQ(tree.listed_lights.area_probability(), 1.0f);
}

// render.light_selection: read from the scene file, refused when unknown, and an image setting a
// checkpoint stores only when it is not "auto", the default.
TEST(EmitterSelection, SceneFileKeyAndCheckpointSetting) {
    const auto scene_text = [](const std::string& render_extra) {
        return R"({"camera": {"eye": [0, 0, 1], "look_at": [0, 0, 0], "up": [0, 1, 0], "fov_degrees": 60},
                   "render": {"width": 4, "height": 4)" + render_extra + R"(},
                   "materials": {"lamp": {"type": "lambertian", "albedo": [0, 0, 0], "emission": [1, 1, 1]}},
                   "shapes": [{"type": "quad", "material": "lamp", "vertices": [[0, 0, 2], [0, 1, 2], [1, 1, 2], [1, 0, 2]]}]})";
    };
    const SceneDescription plain = parse_scene_json(scene_text(""), "test.json");
    EXPECT_EQ(plain.settings.estimator.light_selection, LightSelection::automatic);
    const auto stored = [](const RenderSettings& s) {
        for (const NamedSetting& n : image_settings(s))
            if (n.name == "light_selection") return n.value;
        return std::string();
    };
    EXPECT_EQ(stored(plain.settings), "");
    for (const char* name : {"area", "power", "bvh"}) {
        const SceneDescription d = parse_scene_json(scene_text(std::string(R"(, "light_selection": ")") + name + "\""), "test.json");
        EXPECT_STREQ(name_of(d.settings.estimator.light_selection), name);
        EXPECT_EQ(stored(d.settings), name);
    }
    try {
        parse_scene_json(scene_text(R"(, "light_selection": "tree")"), "test.json");
        ADD_FAILURE() << "accepted light_selection \"tree\"";
    } catch (const std::exception& e) {
        EXPECT_NE(std::string(e.what()).find("render.light_selection"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace wt
