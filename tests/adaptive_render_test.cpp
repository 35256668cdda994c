// Adaptive sampling in the renderer: on a synthetic scene it stops where it should (a region of
// constant radiance at the minimum spp, a noisy one never, the constant pixels beside the noisy
// ones kept), no pixel stops before the minimum or between decision points, the samples AOV
// shows where the samples went; the same bits for any thread count, tile and batch size,
// integrator, split of the range into pieces and checkpoint + resume; what cannot be exact is
// refused.

#include <algorithm>
#include <map>
#include <set>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "core/checkpoint/checkpoint.h"
#include "core/film/aov.h"
#include "core/description/scene_hash.h"
#include "core/system/version.h"
#include "kernels/adaptive/decision_schedule.h"
#include "render_helpers.h"
#include "test_scenes.h"

namespace wt {
namespace {

Material material(const char* name, glm::vec3 albedo, glm::vec3 emission = glm::vec3(0.0f)) {
    Material m;
    m.name = name;
    m.albedo = albedo;
    m.emission = emission;
    return m;
}

// The rectangle x = `x`, y in [y0, y1], z in [z0, z1], facing -x (towards a camera at the origin
// looking along +x) or +x.
TriangleMesh rectangle_at_x(float x, float y0, float y1, float z0, float z1, uint32_t material, bool facing_minus_x) {
    TriangleMesh mesh;
    mesh.vertices = {{x, y0, z0}, {x, y1, z0}, {x, y1, z1}, {x, y0, z1}};
    if (facing_minus_x) mesh.triangles = {{0, 2, 1}, {0, 3, 2}};
    else mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
    mesh.material = material;
    return mesh;
}

// 16x8 pixels. Columns 0-7 see a black emitter of radiance 2 (every sample exactly 2: constant);
// column 8 is half emitter, half a diffuse wall; columns 9-15 see only the wall, lit by a light
// off screen that light sampling finds one sample in 17 (noisy). Screen right is -y.
constexpr int kWidth = 16, kHeight = 8;
SceneDescription half_constant_scene(int spp, float threshold, int min_spp) {
    SceneDescription d;
    d.camera.eye = glm::vec3(0.0f);
    d.camera.look_at = glm::vec3(1, 0, 0);
    d.camera.fov_degrees = 60.0f;
    d.settings.width = kWidth, d.settings.height = kHeight, d.settings.spp = spp;
    d.settings.adaptive.threshold = threshold;
    d.settings.adaptive.min_spp = min_spp;
    d.materials = {material("emitter", glm::vec3(0.0f), glm::vec3(2.0f)), material("wall", glm::vec3(0.5f)),
                   material("lamp", glm::vec3(0.0f), glm::vec3(10.0f))};
    // At x = 3 the view spans y in +-3.46; a pixel column is 0.433 wide, so y = -0.2165 is the
    // middle of column 8.
    const float edge = -0.2165f;
    d.meshes.push_back(rectangle_at_x(3.0f, edge, 4.0f, -2.0f, 2.0f, 0, true));
    d.meshes.push_back(rectangle_at_x(3.0f, -8.0f, edge, -4.0f, 4.0f, 1, true));
    d.meshes.push_back(rectangle_at_x(0.5f, -3.5f, -2.5f, -0.5f, 0.5f, 2, false));
    return d;
}

struct AdaptiveRender {
    Film film;
    RenderResult result;
};

AdaptiveRender render_adaptive(const SceneDescription& d, SampleRange range, int threads = 2,
                               Integrator integrator = Integrator::wavefront, int tile_size = 16,
                               std::size_t batch_paths = 2048, const AovSelection& aovs = {}) {
    const Scene scene = build_scene(d);
    RenderOptions options;
    options.threads = threads;
    options.integrator = integrator;
    options.tile_size = tile_size;
    options.batch_paths = batch_paths;
    options.aovs = aovs;
    AdaptiveRender out{test::film_for(scene, aovs), {}};
    RenderSession session(scene, options);
    session.render_samples(out.film, range);
    out.result = session.result();
    return out;
}

uint32_t stop_of(const Film& film, int x, int y) { return film.adaptive().stopped_at[std::size_t(y * film.width() + x)]; }

TEST(AdaptiveSampling, ConstantRegionStopsAtTheMinimumNoisyRegionKeepsGoing) {
    // A threshold no noisy pixel can meet in 64 samples, and a minimum off the 16-grid.
    const SceneDescription d = half_constant_scene(64, 1e-5f, 24);
    const AdaptiveRender r = render_adaptive(d, {0, 64}, 1);
    const Film& film = r.film;
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x <= 6; ++x) {
            EXPECT_EQ(stop_of(film, x, y), 24u) << x << "," << y;
            EXPECT_EQ(film.pixel_count(uint32_t(y * kWidth + x)), 24u);
            EXPECT_EQ(film.pixel_mean(uint32_t(y * kWidth + x)), glm::dvec3(2.0)) << "constant: every sample 2";
        }
        // Column 7 is constant too, but beside the half-and-half column 8: kept for its neighbour.
        EXPECT_EQ(film.pixel_mean(uint32_t(y * kWidth + 7)), glm::dvec3(2.0));
        EXPECT_TRUE(film.adaptive().sampling(std::size_t(y * kWidth + 7))) << "row " << y;
        for (int x = 8; x < kWidth; ++x) {
            EXPECT_TRUE(film.adaptive().sampling(std::size_t(y * kWidth + x))) << x << "," << y;
            EXPECT_EQ(film.pixel_count(uint32_t(y * kWidth + x)), 64u);
        }
    }
    // Stopped pixels take no more samples: 7 columns of 24 and 9 of 64.
    EXPECT_EQ(r.result.counts.samples, uint64_t(kHeight) * (7 * 24 + 9 * 64));
    // The same scene without adaptive sampling gives every pixel 64.
    SceneDescription off = d;
    off.settings.adaptive.threshold = 0.0f;
    const AdaptiveRender plain = render_adaptive(off, {0, 64}, 1);
    EXPECT_TRUE(plain.film.adaptive().empty());
    EXPECT_EQ(plain.result.counts.samples, uint64_t(kHeight) * kWidth * 64);
    EXPECT_EQ(plain.film.pixel_count(0), 64u);
}

TEST(AdaptiveSampling, NoPixelStopsBeforeTheMinimumOrBetweenDecisions) {
    for (int min_spp : {2, 8, 24}) {
        const SceneDescription d = test::hexroom(24, 18, 80, 3);
        SceneDescription a = d;
        a.settings.adaptive.threshold = 0.3f;
        a.settings.adaptive.min_spp = min_spp;
        const AdaptiveRender r = render_adaptive(a, {0, 80}, 1, Integrator::wavefront, 16, 2048, parse_aov_list("samples"));
        const AdaptiveState& state = r.film.adaptive();
        const ImageChannels layers = resolve_aovs(r.film, parse_aov_list("samples"));
        std::set<uint32_t> stops;
        for (std::size_t p = 0; p < state.stopped_at.size(); ++p) {
            const uint32_t rendered = state.samples_of(p);
            if (!state.sampling(p)) {
                stops.insert(state.stopped_at[p]);
                EXPECT_GE(state.stopped_at[p], uint32_t(min_spp)) << "pixel " << p;
                EXPECT_TRUE(is_decision_point(a.settings.adaptive, state.stopped_at[p])) << state.stopped_at[p];
            }
            // The samples AOV shows where the samples went: the pixel's count, all it was given
            // (the hexroom drops no sample).
            EXPECT_EQ(r.film.pixel_count(uint32_t(p)), rendered);
            EXPECT_EQ(layers.values[p], float(rendered));
        }
        SCOPED_TRACE("min spp " + std::to_string(min_spp));
        EXPECT_GE(stops.size(), 2u) << "pixels stop at several decisions";
        EXPECT_GT(std::count(state.stopped_at.begin(), state.stopped_at.end(), AdaptiveState::still_sampling), 0);
    }
}

// The hexroom at 24x18: with threshold 0.2 and a minimum of 8, pixels stop at 8, 16, 32 and
// 48, and some never (the first test below checks it).
SceneDescription adaptive_hexroom(int spp = 56) {
    SceneDescription d = test::hexroom(24, 18, spp, 5);
    d.settings.adaptive.threshold = 0.2f;
    d.settings.adaptive.min_spp = 8;
    return d;
}

TEST(AdaptiveDeterminism, SameBitsForAnyThreadsTilesBatchesAndIntegrator) {
    const SceneDescription d = adaptive_hexroom();
    const AdaptiveRender base = render_adaptive(d, {0, 56}, 1);
    std::map<uint32_t, int> stops;
    for (uint32_t stop : base.film.adaptive().stopped_at) ++stops[stop];
    std::string histogram;
    for (const auto& [stop, pixels] : stops) histogram += " " + std::to_string(stop) + ":" + std::to_string(pixels);
    EXPECT_TRUE(stops.count(8) && stops.count(16) && stops.count(32) && stops.count(AdaptiveState::still_sampling))
        << "the test needs pixels stopping at several decisions, and pixels that never stop; stops:" << histogram;
    EXPECT_TRUE(base.film == render_adaptive(d, {0, 56}, 3).film);
    EXPECT_TRUE(base.film == render_adaptive(d, {0, 56}, 2, Integrator::wavefront, 5, 7).film);
    EXPECT_TRUE(base.film == render_adaptive(d, {0, 56}, 3, Integrator::wavefront, 7, 100000).film);
    EXPECT_TRUE(base.film == render_adaptive(d, {0, 56}, 2, Integrator::reference, 5).film);
    // And it is not the render without adaptive sampling.
    SceneDescription off = d;
    off.settings.adaptive.threshold = 0.0f;
    EXPECT_FALSE(base.film == render_adaptive(off, {0, 56}, 2).film);
}

TEST(AdaptiveDeterminism, OneRangeOrManyPiecesGiveTheSameBits) {
    const SceneDescription d = adaptive_hexroom();
    const Film whole = render_adaptive(d, {0, 56}, 2).film;
    const std::vector<std::vector<uint32_t>> cuts = {
        {0, 1, 2, 4, 8, 16, 32, 56},          // the progressive passes, each ending at a decision point
        {0, 3, 9, 17, 31, 33, 48, 49, 56},    // anywhere
        {0, 8, 9, 16, 17, 32, 33, 48, 49, 56}};
    for (const std::vector<uint32_t>& cut : cuts) {
        const Scene scene = build_scene(d);
        RenderOptions options;
        options.threads = 3;
        RenderSession session(scene, options);
        Film film = test::film_for(scene);
        for (std::size_t i = 0; i + 1 < cut.size(); ++i) session.render_samples(film, {cut[i], cut[i + 1]});
        EXPECT_TRUE(film == whole) << "cut at " << cut[1] << ", " << cut[2] << ", ...";
    }
}

Film through_checkpoint(const SceneDescription& d, const Film& film, uint32_t next) {
    const CheckpointHeader header{program_version(), scene_content_hash(d), 0, next, uint32_t(d.settings.spp),
                                  image_settings(d.settings)};
    return parse_checkpoint(checkpoint_bytes(header, film), "adaptive.ckpt").film;
}

TEST(AdaptiveDeterminism, CheckpointAndResumeGiveTheSameBits) {
    const SceneDescription d = adaptive_hexroom();
    const Film whole = render_adaptive(d, {0, 56}, 2).film;
    for (uint32_t stop : {3u, 8u, 16u, 21u, 48u}) {
        const Film before = render_adaptive(d, {0, stop}, 1).film;
        const Film back = through_checkpoint(d, before, stop);
        EXPECT_TRUE(back == before) << "the state comes back bit for bit";
        const Scene scene = build_scene(d);
        RenderOptions options;
        options.threads = 3;
        options.integrator = stop % 2 ? Integrator::reference : Integrator::wavefront;
        RenderSession session(scene, options);
        Film resumed = back;
        session.render_samples(resumed, {stop, 56});
        EXPECT_TRUE(resumed == whole) << "stopped at sample " << stop;
    }
    // A finished render raised to more samples is the render of the more samples.
    const SceneDescription shorter = adaptive_hexroom(24);
    const Film finished = render_adaptive(shorter, {0, 24}, 2).film;
    const Scene scene = build_scene(d);
    RenderSession session(scene, RenderOptions{});
    Film raised = through_checkpoint(shorter, finished, 24);
    session.render_samples(raised, {24, 56});
    EXPECT_TRUE(raised == whole);
}

TEST(AdaptiveSampling, RangesThatCannotBeExactAreRefused) {
    const SceneDescription d = adaptive_hexroom();
    const Scene scene = build_scene(d);
    RenderSession session(scene, RenderOptions{});
    const auto message = [&](Film& film, SampleRange range) {
        try {
            session.render_samples(film, range);
        } catch (const std::invalid_argument& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    // A part of a split render lacks the samples before it.
    Film part = test::film_for(scene);
    EXPECT_NE(message(part, {16, 32}).find("must start at sample 0"), std::string::npos);
    EXPECT_TRUE(part.adaptive().empty()) << "nothing rendered";
    // A film must continue where it ended.
    Film film = test::film_for(scene);
    session.render_samples(film, {0, 10});
    EXPECT_NE(message(film, {12, 20}).find("holds samples up to 10"), std::string::npos);
    // Adding films of an adaptive render (a merge, MPI) would mix decisions.
    Film other = film;
    EXPECT_THROW(other.add_film(film), std::invalid_argument);
    // A film of an adaptive render in a render without it.
    SceneDescription off = d;
    off.settings.adaptive.threshold = 0.0f;
    const Scene plain = build_scene(off);
    RenderSession plain_session(plain, RenderOptions{});
    try {
        plain_session.render_samples(film, {10, 20});
        ADD_FAILURE() << "accepted";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("adaptive sampling"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace wt
