// The photon grid against a brute-force search of every photon (the same set, the same estimate
// bits), rebuilt in place and built by threads against a fresh one-thread build; when the photon
// maps build a batch's grids ahead; the radius schedule against its closed form, the automatic
// and requested radii, and the scene file's refusal of bad radii.

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "core/system/thread_pool.h"
#include "kernels/photons/photon_gather.h"
#include "kernels/photons/photon_grid.h"
#include "kernels/photons/photon_maps.h"
#include "kernels/photons/photon_radius.h"
#include "scene_test_helpers.h"
#include "test_scenes.h"

namespace wt {
namespace {

// Photons in clusters about a few centres, and on a plane (z = 0) so that gathers see many.
PhotonList random_photons(std::size_t n, float scale, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    PhotonList photons;
    for (std::size_t i = 0; i < n; ++i) {
        const float spread = i % 3 == 0 ? 0.05f : 1.0f;
        const glm::vec3 centre = i % 3 == 0 ? glm::vec3(0.3f, -0.2f, 0.0f) : glm::vec3(0.0f);
        const glm::vec3 p = (centre + spread * glm::vec3(u(rng), u(rng), i % 2 ? 0.0f : 0.1f * u(rng))) * scale;
        const glm::vec3 arriving = glm::normalize(glm::vec3(u(rng), u(rng), -1.0f - std::fabs(u(rng))));
        photons.push_back({p, arriving, {0, 0, 1}, glm::vec3(0.5f + u(rng), 1.0f, 2.0f) * 1e-3f, 2 + uint32_t(i % 3)});
    }
    return photons;
}

// Every photon within the radius, by index: the grid's (sorted) against a loop over all.
void expect_grid_matches_brute_force(const PhotonList& photons, float radius, float scale, uint32_t seed) {
    const PhotonList second(photons.begin() + photons.size() / 2, photons.end());
    const PhotonList first(photons.begin(), photons.begin() + photons.size() / 2);
    const PhotonGrid grid({&first, &second}, radius);  // two parts: indices run on across them
    ASSERT_EQ(grid.size(), photons.size());
    Material floor;
    floor.albedo = glm::vec3(0.7f);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    std::size_t found_total = 0;
    for (int q = 0; q < 300; ++q) {
        // Query points at photons (exact hits and the boundary's neighbourhood) and anywhere.
        glm::vec3 x = glm::vec3(u(rng), u(rng), 0.0f) * scale;
        if (q % 3 == 0) x = photons[std::size_t(q) % photons.size()].position;
        if (q % 3 == 1) x = photons[std::size_t(q) % photons.size()].position + glm::vec3(radius, 0.0f, 0.0f);
        std::vector<uint32_t> from_grid, from_all;
        grid.for_each_within(x, [&](const Photon&, uint32_t i) { from_grid.push_back(i); });
        const float r2 = radius * radius;
        for (uint32_t i = 0; i < photons.size(); ++i) {
            const glm::vec3 v = photons[i].position - x;
            if (glm::dot(v, v) <= r2) from_all.push_back(i);
        }
        std::sort(from_grid.begin(), from_grid.end());
        ASSERT_EQ(from_grid, from_all) << "query " << q;
        found_total += from_all.size();

        SurfacePoint s{x, glm::vec3(0.0f), {0, 0, 1}, {0, 0, 1}, 0, false};
        const glm::vec3 d = glm::normalize(glm::vec3(0.2f, 0.5f, -1.0f));
        const PhotonGather g = gather_photons(grid, floor, s, d, 3);
        const PhotonGather all = gather_photons_from(
            [&](auto&& visit) {
                for (uint32_t i : from_all) visit(photons[i], i);
            },
            radius, floor, s, d, 3);
        ASSERT_EQ(g.photons, all.photons) << "query " << q;
        ASSERT_EQ(g.radiance, all.radiance) << "query " << q;  // bit for bit: the sum is exact
    }
    // A third of the queries sit on a photon and find it; more means they found neighbours too.
    EXPECT_GT(found_total, 100u) << "the queries must find photons beyond their own";
}

TEST(PhotonGrid, FindsExactlyThePhotonsABruteForceSearchFinds) {
    expect_grid_matches_brute_force(random_photons(4000, 1.0f, 1), 0.03f, 1.0f, 2);
}

// Far from the origin with a radius small beside the coordinates (cells of large index), and with
// so few photons that the table has a handful of buckets: the eight cells of a lookup share
// buckets, which must still be read once each.
TEST(PhotonGrid, FarFromTheOriginAndWithBucketsSharedByCells) {
    expect_grid_matches_brute_force(random_photons(3000, 1e4f, 3), 5.0f, 1e4f, 4);
    expect_grid_matches_brute_force(random_photons(6, 1.0f, 5), 0.5f, 1.0f, 6);
}

// Photons just inside the radius along each axis of many points: wherever the cell boundaries
// fall, a lookup reaches every cell that can hold one of them.
TEST(PhotonGrid, FindsPhotonsAtTheRadiusWhereverTheCellBoundariesFall) {
    const float r = 0.01f, inside = r * (1.0f - 0x1p-20f);
    std::mt19937 rng(9);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::vector<glm::vec3> centres;
    PhotonList photons;
    for (int i = 0; i < 4000; ++i) {
        // On a lattice 10 r apart, jittered: no point sees another's photons.
        const glm::vec3 c = glm::vec3(float(i % 20), float(i / 20 % 20), float(i / 400)) * (10.0f * r) +
                            glm::vec3(u(rng), u(rng), u(rng)) * (2.0f * r);
        centres.push_back(c);
        for (int axis = 0; axis < 3; ++axis)
            for (const float sign : {-1.0f, 1.0f}) {
                glm::vec3 p = c;
                p[axis] += sign * inside;
                photons.push_back({p, {0, 0, -1}, {0, 0, 1}, glm::vec3(1.0f), 2});
            }
    }
    const PhotonGrid grid({&photons}, r);
    for (std::size_t i = 0; i < centres.size(); ++i) {
        int found = 0;
        grid.for_each_within(centres[i], [&](const Photon&, uint32_t index) { found += index / 6 == i; });
        ASSERT_EQ(found, 6) << "point " << i;
    }
}

// What a lookup at x visits, in the grid's order: (index, power.x) per photon.
std::vector<std::pair<uint32_t, float>> lookup(const PhotonGrid& grid, const glm::vec3& x) {
    std::vector<std::pair<uint32_t, float>> visited;
    grid.for_each_within(x, [&](const Photon& p, uint32_t i) { visited.emplace_back(i, p.power.x); });
    return visited;
}

// `grid` against a fresh single-threaded build of the same photons: the same photons in the same
// order at 200 points (half of them on photons). Returns how many photons the lookups found.
std::size_t expect_same_lookups_as_a_fresh_grid(const PhotonGrid& grid, const std::vector<const PhotonList*>& parts,
                                                float radius, uint32_t seed) {
    const PhotonGrid fresh(parts, radius);
    EXPECT_EQ(grid.size(), fresh.size());
    EXPECT_EQ(grid.radius(), radius);
    PhotonList all;
    for (const auto* part : parts) all.insert(all.end(), part->begin(), part->end());
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    std::size_t found = 0;
    for (int q = 0; q < 200; ++q) {
        const glm::vec3 x =
            q % 2 == 0 && !all.empty() ? all[std::size_t(q) * 7 % all.size()].position : glm::vec3(u(rng), u(rng), 0.0f);
        const auto expected = lookup(fresh, x);
        EXPECT_EQ(lookup(grid, x), expected) << all.size() << " photons, query " << q;
        for (const auto& [i, power] : expected) EXPECT_EQ(power, all[i].power.x);
        found += expected.size();
    }
    return found;
}

// A render rebuilds one grid per sample in the same memory (PhotonMaps): after holding more
// photons at another radius, or fewer, a rebuilt grid finds exactly what a fresh one finds, in
// the same order, with nothing of the grid before.
TEST(PhotonGrid, RebuiltInPlaceFindsWhatAFreshGridFinds) {
    PhotonGrid reused;
    struct Build {
        std::size_t photons;
        float radius;
    };
    for (const Build b : {Build{5000, 0.05f}, Build{700, 0.02f}, Build{9000, 0.03f}, Build{0, 0.1f}, Build{3000, 0.2f}}) {
        const PhotonList photons = random_photons(b.photons, 1.0f, uint32_t(b.photons));
        reused.build({&photons}, b.radius);
        const std::size_t found = expect_same_lookups_as_a_fresh_grid(reused, {&photons}, b.radius, 11);
        if (b.photons > 0) EXPECT_GT(found, 100u) << b.photons << " photons: the queries must find photons";
        else EXPECT_EQ(found, 0u);
    }
}

// Built by a pool's threads (the buckets split in one range per thread, each bucket's photons in
// input order): the same grid as one thread's, for any thread count, from many parts or one,
// also rebuilt in place, and with fewer buckets than threads.
TEST(PhotonGrid, BuiltWithThreadsIsTheGridOneThreadBuilds) {
    const PhotonList photons = random_photons(20000, 1.0f, 21);
    std::vector<PhotonList> lists;
    for (std::size_t begin = 0; begin < photons.size(); begin += 1500)
        lists.emplace_back(photons.begin() + begin, photons.begin() + std::min(photons.size(), begin + 1500));
    std::vector<const PhotonList*> many;
    for (const PhotonList& l : lists) many.push_back(&l);
    const PhotonList few(photons.begin(), photons.begin() + 3);
    for (const int threads : {2, 3, 5}) {
        ThreadPool pool(threads);
        PhotonGrid grid;
        grid.build(many, 0.03f, &pool);
        EXPECT_GT(expect_same_lookups_as_a_fresh_grid(grid, many, 0.03f, 12), 100u) << threads << " threads";
        grid.build({&photons}, 0.05f, &pool);
        EXPECT_GT(expect_same_lookups_as_a_fresh_grid(grid, {&photons}, 0.05f, 13), 100u) << threads << " threads";
        grid.build({&few}, 0.5f, &pool);  // 4 buckets
        EXPECT_GE(expect_same_lookups_as_a_fresh_grid(grid, {&few}, 0.5f, 14), 100u) << threads << " threads";
    }
}

// A batch's maps are built before its camera paths, by the pool, only once the batch before was
// asked for one (a render whose camera paths see photons asks every batch); otherwise on a camera
// path's first ask. A map built ahead is the grid a fresh build of the sample's lists gives.
TEST(PhotonMaps, BuildsABatchsMapsAheadOnlyAfterTheBatchBeforeAskedForOne) {
    const Scene scene = build_scene(test::hexroom(8, 8, 1, 1));
    PhotonMaps maps(scene);
    ThreadPool pool(2);
    const PhotonList photons = random_photons(3000, 1.0f, 31);
    const auto start = [&](uint32_t begin, uint32_t end) {  // two lists a sample, a third of the photons each
        maps.start_batch(begin, end, 2);
        for (std::size_t item = 0; item < 2 * std::size_t(end - begin); ++item)
            maps.photons(item).assign(photons.begin() + (item % 3) * 1000, photons.begin() + (item % 3 + 1) * 1000);
    };
    start(0, 2);
    maps.build_if_asked_before(pool);  // nothing asked yet
    EXPECT_EQ(maps.maps_built(), 0u);
    maps.end_batch();
    start(2, 4);
    maps.build_if_asked_before(pool);  // the batch before asked for nothing
    EXPECT_EQ(maps.maps_built(), 0u);
    EXPECT_EQ(maps.map(3).size(), 2000u);  // built on the ask
    EXPECT_EQ(maps.maps_built(), 1u);
    maps.end_batch();
    start(4, 6);
    maps.build_if_asked_before(pool);  // the batch before asked: both maps now
    EXPECT_EQ(maps.maps_built(), 3u);
    const PhotonGrid& ahead = maps.map(5);  // built already: no second build
    EXPECT_EQ(maps.maps_built(), 3u);
    const PhotonList first(photons.begin() + 2000, photons.end()), second(photons.begin(), photons.begin() + 1000);
    EXPECT_GT(expect_same_lookups_as_a_fresh_grid(ahead, {&first, &second}, ahead.radius(), 32), 100u);
    maps.end_batch();
    start(6, 7);
    maps.build_if_asked_before(pool);  // asked for sample 5
    EXPECT_EQ(maps.maps_built(), 4u);
    maps.end_batch();
    start(7, 8);
    maps.build_if_asked_before(pool);  // the batch of sample 6 built its map ahead, but no one asked
    EXPECT_EQ(maps.maps_built(), 4u);
    maps.end_batch();
}

TEST(PhotonGrid, GatherCountsOnlyPhotonsFromTheViewedSideWithinTheVertexLimit) {
    Material floor;
    floor.albedo = glm::vec3(0.5f);
    const glm::vec3 down(0, 0, -1);
    PhotonList photons = {
        {{0, 0, 0}, down, {0, 0, 1}, glm::vec3(1.0f), 2},              // counted
        {{0.1f, 0, 0}, -down, {0, 0, -1}, glm::vec3(1.0f), 2},         // arrived from below
        {{0, 0.1f, 0}, down, {0, 0, 1}, glm::vec3(1.0f), 4},           // too many vertices for the limit 3
        {{0, 0, 0.05f}, glm::vec3(1, 0, 0), {-1, 0, 0}, glm::vec3(1.0f), 2},  // on a wall at right angles
    };
    const PhotonGrid grid({&photons}, 0.2f);
    const SurfacePoint s{{0, 0, 0}, glm::vec3(0.0f), {0, 0, 1}, {0, 0, 1}, 0, false};
    const PhotonGather g = gather_photons(grid, floor, s, glm::normalize(glm::vec3(0, 1, -1)), 3);
    EXPECT_EQ(g.photons, 1u);
    // rho / pi * power / (pi r^2), in float as the gather rounds it.
    const double expected = 0.5 / M_PI / (M_PI * 0.2 * 0.2);
    EXPECT_NEAR(g.radiance.x, expected, 1e-6 * expected);
    EXPECT_EQ(gather_photons(grid, floor, s, glm::normalize(glm::vec3(0, 1, -1)), 4).photons, 2u);
}

// r_s^2 / r_0^2 = prod_{i=1}^{s} (i + alpha) / (i + 1) = Gamma(s + 1 + alpha) / (Gamma(1 + alpha) Gamma(s + 2)),
// to the rounding of thousands of products and of lgamma's large values (about 1e-11).
TEST(PhotonRadius, ScheduleIsAPureFunctionOfTheSampleAndMatchesItsClosedForm) {
    PhotonRadiusSchedule walked(0.5);
    const double a = kPhotonRadiusAlpha;
    for (uint32_t s : {0u, 1u, 2u, 7u, 100u, 5000u, 3u, 100u}) {
        const double closed = 0.25 * std::exp(std::lgamma(s + 1 + a) - std::lgamma(1 + a) - std::lgamma(s + 2.0));
        EXPECT_NEAR(walked.squared(s), closed, 1e-10 * closed) << "sample " << s;
        EXPECT_EQ(walked.squared(s), PhotonRadiusSchedule(0.5).squared(s)) << "sample " << s << ": memory showed";
    }
    EXPECT_EQ(walked.squared(0), 0.25);
    EXPECT_LT(walked.squared(1), walked.squared(0));
}

TEST(PhotonRadius, RequestedRadiusIsUsedUpToTheScenesDiagonalAndTheAutomaticOneFollowsThePixels) {
    SceneDescription d = test::hexroom(40, 30, 1);
    d.settings.estimator.photon_radius = 0.05f;
    EXPECT_FLOAT_EQ(float(initial_photon_radius(build_scene(d))), 0.05f);
    d.settings.estimator.photon_radius = 1e18f;
    const double diagonal = initial_photon_radius(build_scene(d));
    EXPECT_LT(diagonal, 1e3);
    EXPECT_GT(diagonal, 1.0);
    d.settings.estimator.photon_radius = 0.0f;
    const double automatic = initial_photon_radius(build_scene(d));
    EXPECT_GT(automatic, 0.0);
    EXPECT_LT(automatic, 0.1 * diagonal);
    d.settings.width = 80, d.settings.height = 60;  // pixels half as wide: half the radius
    EXPECT_NEAR(initial_photon_radius(build_scene(d)), 0.5 * automatic, 1e-3 * automatic);
}

TEST(PhotonRadius, SceneFileRefusesARadiusThatIsNotPositiveOrTooLarge) {
    for (const double bad : {0.0, -1.0, 1e19})
        expect_scene_error(mutated([&](Json& j) { j["render"]["photon_radius"] = bad; }), "render.photon_radius: must be greater than 0");
    expect_scene_error(mutated([](Json& j) { j["render"]["caustics"] = "photon"; }),
                       "render.caustics: must be one of \"path\", \"light_tracing\", \"photons\"");
    const SceneDescription ok = parse_scene_json(mutated([](Json& j) { j["render"]["photon_radius"] = 0.25; }), "ok.json");
    EXPECT_EQ(ok.settings.estimator.photon_radius, 0.25f);
}

}  // namespace
}  // namespace wt
