// The renderer against an oracle that shares no code with it (tests/oracle): a radiosity
// solution of an all-Lambertian closed room, from its own geometry, exact form factors and
// linear solve, compared region by region with renders of the same room loaded from a scene
// file (oracle_room.h, oracle_comparison.h). WavefrontVsReference compares two integrators that
// run the same path_vertex.h; this sees a bias in the code they share.
//
// Direct and indirect light are checked apart. max_bounces 1 renders light reflected once,
// which the oracle knows in closed form. The ceiling is lit only indirectly (the light is set
// into it), so the ceiling view shows indirect light alone. Each check also renders the room
// with a 1 % bias injected (albedos scaled by 1.01 in the scene file, not in the oracle) and
// requires the comparison to fail on it: the test's power, asserted with its pass.
//
// Compiled twice: oracle_test (CI: a few seconds) and oracle_long_test (WT_LONG_TESTS=1, label
// `long`: 8x the samples, finer patches, and the convergence order the oracle's bound assumes).

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "core/scene/scene.h"
#include "core/scene_file/scene_loader.h"
#include "kernels/renderer.h"
#include "oracle/radiosity_solver.h"
#include "oracle/region_prediction.h"
#include "oracle_comparison.h"
#include "oracle_room.h"
#include "oracle_scenes.h"

#ifndef WT_LONG_TESTS
#define WT_LONG_TESTS 0
#endif

namespace wt {
namespace {

constexpr bool kLong = WT_LONG_TESTS != 0;
constexpr int kSampleScale = kLong ? 8 : 1;

oracle::OracleSettings oracle_settings() {
    oracle::OracleSettings s;
    s.coarse_patch = kLong ? 1.0 / 24.0 : 1.0 / 16.0;
    s.fine_patch = kLong ? 1.0 / 32.0 : 1.0 / 24.0;
    return s;
}

struct RoomRender {
    Film film;
    std::string scene_file;
    test::OracleRender settings;
};

// Writes the room as `name`.json in the working directory (build/tests under ctest), loads it
// like any scene file and renders it on two threads.
RoomRender render_room(const oracle::Room& room, const oracle::PinholeCamera& camera, const test::OracleRender& settings,
                       const std::string& name) {
    const std::string path = (std::filesystem::current_path() / (name + (kLong ? "_long.json" : ".json"))).string();
    test::write_scene_file(path, test::scene_json(room, camera, settings));
    const Scene scene = build_scene(load_scene_file(path));
    RenderOptions options;
    options.threads = 2;
    RoomRender r{Film(camera.width, camera.height), path, settings};
    const RenderResult result = render(scene, options, r.film);
    EXPECT_EQ(result.counts.nonfinite_samples, 0u);
    return r;
}

std::string replay(const RoomRender& r) {
    return "the scene " + r.scene_file + " (seed " + std::to_string(r.settings.seed) + ", " + std::to_string(r.settings.spp) +
           " spp, max_bounces " + std::to_string(r.settings.max_bounces) + ", all in the file); replay: build/bin/wavetrace render " +
           r.scene_file + " -o oracle.exr";
}

// Every region within its tolerance, and the oracle's own error well inside that tolerance (a
// third at most), so that what is tested is the renderer.
void expect_agrees(const test::OracleComparison& c, const RoomRender& r, const char* what) {
    std::printf("%s: %s, largest |z| %.2f of %.2f, oracle bound at most %.0f %% of the tolerance\n", what,
                c.failures ? "FAILS" : "agrees", c.largest_z, c.z_limit, 100.0 * c.largest_oracle_share);
    if (c.failures) test::print_comparison(c, what);
    EXPECT_EQ(c.failures, 0) << what << " disagrees with the radiosity oracle; " << replay(r);
    EXPECT_LT(c.largest_oracle_share, 1.0 / 3.0) << what << ": the oracle's error is not negligible; " << replay(r);
}

void expect_disagrees(const test::OracleComparison& c, const RoomRender& r, const char* what) {
    std::printf("%s: %s, largest |z| %.2f of %.2f\n", what, c.failures ? "caught" : "NOT CAUGHT", c.largest_z, c.z_limit);
    if (!c.failures) test::print_comparison(c, what);
    EXPECT_GT(c.failures, 0) << what << " was not caught; " << replay(r);
}

oracle::Room scaled_albedo(oracle::Room room, int only_wall, double factor) {
    for (int w = 0; w < oracle::kWalls; ++w)
        if (only_wall < 0 || w == only_wall)
            for (double& a : room.albedo[std::size_t(w)]) a *= factor;
    return room;
}

// Light reflected once (max_bounces 1): next-event estimation at the first hit, which the oracle
// has in closed form (rho Le times the point's form factor to the light). Every wall's albedo
// times 1.01 makes all of it 1 % brighter, exactly.
TEST(RadiosityOracle, DirectLightAgreesAndOnePercentMoreIsCaught) {
    const oracle::Room room = test::oracle_room();
    const oracle::PinholeCamera view = test::oracle_room_view();
    const test::OracleRender settings{128 * kSampleScale, /*seed=*/1, /*max_bounces=*/1};
    const oracle::RoomOracle oracle(room, settings.max_bounces, oracle_settings());
    const oracle::ViewPrediction predicted = oracle.predict(view);

    const RoomRender right = render_room(room, view, settings, "oracle_direct");
    expect_agrees(test::compare_with_oracle(right.film, predicted), right, "direct light");

    const RoomRender biased = render_room(scaled_albedo(room, -1, 1.01), view, settings, "oracle_direct_1pc_brighter");
    expect_disagrees(test::compare_with_oracle(biased.film, predicted), biased, "direct light 1 % brighter");
}

// The mean over a view's regions of each solution's indirect radiance at the pixel centres.
oracle::Rgb mean_indirect(const oracle::RadiositySolution& s, const oracle::Room& room, const oracle::PinholeCamera& view) {
    oracle::Rgb sum{0, 0, 0};
    int n = 0;
    for (const oracle::PixelRegion& r : oracle::pixel_regions(room, view, oracle_settings())) {
        if (r.cell_a >= 0) continue;
        for (int p : r.pixels) {
            const oracle::WallPoint w = oracle::seen_at(room, view, p % view.width + 0.5, p / view.width + 0.5);
            const oracle::Rgb l = s.indirect_radiance(w.wall, w.point);
            for (int c = 0; c < 3; ++c) sum[c] += l[c];
            ++n;
        }
    }
    for (double& v : sum) v /= n;
    return sum;
}

// All light (max_bounces at its default, 64): the room view, direct and indirect together, and
// the ceiling view, indirect alone. The ceiling's albedo times 1.01 makes the indirect light it
// shows about 1 % brighter (a little more: the ceiling also lights itself, via the walls), which
// the oracle itself measures here.
TEST(RadiosityOracle, AllLightAgreesAndOnePercentMoreIndirectLightIsCaught) {
    const oracle::Room room = test::oracle_room();
    const oracle::PinholeCamera room_view = test::oracle_room_view(), ceiling_view = test::oracle_ceiling_view();
    const test::OracleRender ceiling_settings{512 * kSampleScale, /*seed=*/2, /*max_bounces=*/64};
    const test::OracleRender room_settings{256 * kSampleScale, /*seed=*/3, /*max_bounces=*/64};
    const oracle::RoomOracle oracle(room, 64, oracle_settings());

    const RoomRender all = render_room(room, room_view, room_settings, "oracle_all_light");
    expect_agrees(test::compare_with_oracle(all.film, oracle.predict(room_view)), all, "all light, room view");

    const oracle::ViewPrediction ceiling = oracle.predict(ceiling_view);
    const RoomRender indirect = render_room(room, ceiling_view, ceiling_settings, "oracle_indirect");
    expect_agrees(test::compare_with_oracle(indirect.film, ceiling), indirect, "indirect light, ceiling view");

    const oracle::Room brighter_ceiling = scaled_albedo(room, oracle::kCeiling, 1.01);
    const oracle::RadiositySolution brighter(brighter_ceiling, oracle.coarse_cells(), 64);
    const oracle::Rgb before = mean_indirect(oracle.coarse(), room, ceiling_view), after = mean_indirect(brighter, room, ceiling_view);
    for (int c = 0; c < 3; ++c) {
        const double bias = after[c] / before[c] - 1.0;
        std::printf("ceiling albedo x 1.01: the ceiling view's indirect light %.3f %% brighter (channel %d)\n", 100.0 * bias, c);
        EXPECT_GE(bias, 0.01);
        EXPECT_LT(bias, 0.0125);  // still a 1 % bias, not a larger one
    }
    const RoomRender biased = render_room(brighter_ceiling, ceiling_view, ceiling_settings, "oracle_indirect_1pc_brighter");
    expect_disagrees(test::compare_with_oracle(biased.film, ceiling), biased, "indirect light 1 % brighter");
}

}  // namespace
}  // namespace wt
