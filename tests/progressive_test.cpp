// Progressive passes, sample ranges and split films: the image never depends on how a render
// was cut up, the pass schedule follows its rules, and the time limit and stop are honoured.

#include <atomic>
#include <vector>

#include <gtest/gtest.h>

#include "kernels/progressive_render.h"
#include "render_helpers.h"
#include "test_scenes.h"

namespace wt {
namespace {

RenderOptions options_for(Integrator integrator, int threads) {
    RenderOptions o;
    o.integrator = integrator;
    o.threads = threads;
    return o;
}

class PassRecorder : public PassObserver {
public:
    std::vector<PassReport> passes;
    uint64_t samples = 0;
    std::atomic<uint64_t> samples_from_workers{0};
    void samples_done(uint64_t n) override { samples_from_workers += n; }
    bool pass_done(const Film& film, const PassReport& report) override {
        passes.push_back(report);
        // At a boundary every pixel has the same count: an honest N-spp image.
        for (uint32_t p = 0; p < film.pixel_total(); ++p)
            EXPECT_EQ(film.pixel_count(p), report.film_spp) << "pixel " << p << " after pass " << report.pass;
        return true;
    }
};

TEST(Progressive, PassesGiveTheOneShotFilmBitForBitWithEitherIntegrator) {
    const SceneDescription d = test::hexroom(24, 16, 13, 5);
    const Scene scene = build_scene(d);
    for (Integrator integrator : {Integrator::wavefront, Integrator::reference}) {
        SCOPED_TRACE(integrator == Integrator::wavefront ? "wavefront" : "reference");
        const test::RenderedFilm one_shot = test::render_film(d, integrator, 1);
        RenderSession session(scene, options_for(integrator, 2));
        Film film = test::film_for(scene);
        ProgressiveOptions po;
        po.samples = {0, uint32_t(d.settings.spp)};
        PassRecorder recorder;
        const ProgressiveResult r = render_progressive(session, film, po, &recorder);
        EXPECT_EQ(r.reason, StopReason::finished);
        EXPECT_EQ(r.end_sample, 13u);
        EXPECT_TRUE(film == one_shot.film);
        ASSERT_GE(recorder.passes.size(), 3u);
        EXPECT_EQ(recorder.passes[0].film_spp, 1u);
        EXPECT_EQ(recorder.passes[1].film_spp, 2u);
        EXPECT_TRUE(recorder.passes.back().last);
        EXPECT_EQ(recorder.samples_from_workers.load(), film.pixel_total() * 13u);
    }
}

TEST(Progressive, RangesRenderedIntoSeparateFilmsAddToTheWholeRender) {
    const SceneDescription d = test::hexroom(20, 12, 11, 3);
    const Scene scene = build_scene(d);
    const test::RenderedFilm whole = test::render_film(d, Integrator::wavefront, 2);
    RenderSession session(scene, options_for(Integrator::wavefront, 3));
    // A resumed render (into the same film) and a split one (separate films, merged backwards).
    Film resumed = test::film_for(scene);
    session.render_samples(resumed, {0, 4});
    session.render_samples(resumed, {4, 11});
    EXPECT_TRUE(resumed == whole.film);
    std::vector<Film> parts;
    for (SampleRange range : {SampleRange{0, 2}, SampleRange{2, 7}, SampleRange{7, 11}}) {
        parts.push_back(test::film_for(scene));
        session.render_samples(parts.back(), range);
    }
    Film merged = parts[2];
    merged.add_film(parts[0]);
    merged.add_film(parts[1]);
    EXPECT_TRUE(merged == whole.film);
    EXPECT_FALSE(parts[0] == whole.film) << "a part alone is not the whole";
}

// "Add samples to a finished render": no sampler's numbers depend on the spp a render asks for,
// so 8 spp continued to 20 is the 20-spp render, with each sampler.
TEST(Progressive, RaisingTheSppOfAFinishedRenderGivesTheRenderOfTheLargerSpp) {
    for (SamplerKind sampler : {SamplerKind::independent, SamplerKind::stratified, SamplerKind::sobol}) {
        SCOPED_TRACE(name_of(sampler));
        SceneDescription d = test::hexroom(16, 12, 8, 4);
        d.settings.estimator.sampler = sampler;
        const Scene eight = build_scene(d);
        Film film = test::film_for(eight);
        RenderSession(eight, options_for(Integrator::wavefront, 2)).render_samples(film, {0, 8});
        d.settings.spp = 20;
        const Scene twenty = build_scene(d);
        RenderSession(twenty, options_for(Integrator::wavefront, 2)).render_samples(film, {8, 20});
        EXPECT_TRUE(film == test::render_film(d, Integrator::wavefront, 1).film);
    }
}

TEST(Progressive, PassesDoubleTheImageSppUntilAPassWouldTakeTooLong) {
    EXPECT_EQ(next_pass_size(0, 100, 0.0, 2.0, 1e9), 1u);
    EXPECT_EQ(next_pass_size(1, 100, 0.0, 2.0, 1e9), 1u) << "no speed known yet: double";
    EXPECT_EQ(next_pass_size(8, 100, 0.01, 2.0, 1e9), 8u) << "8 more spp take 0.08 s";
    EXPECT_EQ(next_pass_size(64, 1000, 0.1, 2.0, 1e9), 20u) << "capped at 2 s of rendering";
    EXPECT_EQ(next_pass_size(64, 1000, 10.0, 2.0, 1e9), 1u) << "never less than one sample";
    EXPECT_EQ(next_pass_size(64, 5, 0.01, 2.0, 1e9), 5u) << "never past the end";
    EXPECT_EQ(next_pass_size(64, 0, 0.01, 2.0, 1e9), 0u);
}

TEST(Progressive, NoPassStartsThatTheMeasuredSpeedSaysWouldEndPastTheTimeLimit) {
    EXPECT_EQ(next_pass_size(64, 1000, 0.1, 2.0, 0.55), 5u);
    EXPECT_EQ(next_pass_size(64, 1000, 0.1, 2.0, 0.05), 0u) << "not even one spp fits: stop";
}

// A clock that advances one second per sample of every pixel, driven by the workers' progress:
// deterministic, so the time limit's arithmetic is tested without waiting for anything.
class SampleClock : public PassRecorder {
public:
    explicit SampleClock(uint64_t pixels) : pixels_(pixels) {}
    double now() const { return double(samples_from_workers.load()) / double(pixels_); }

private:
    uint64_t pixels_;
};

TEST(Progressive, TheTimeLimitEndsAtTheLastPassBoundaryThatFits) {
    const SceneDescription d = test::hexroom(8, 8, 100, 1);
    const Scene scene = build_scene(d);
    RenderSession session(scene, options_for(Integrator::wavefront, 2));
    Film film = test::film_for(scene);
    SampleClock clock(64);
    ProgressiveOptions po;
    po.samples = {0, 100};
    po.time_limit = 10.5;
    po.pass_seconds = 1000.0;
    po.clock = [&clock] { return clock.now(); };
    const ProgressiveResult r = render_progressive(session, film, po, &clock);
    // Passes of 1, 1, 2, 4 spp end at 8 s; 2 more fit in the 2.5 s left, then none does.
    EXPECT_EQ(r.reason, StopReason::time_limit);
    EXPECT_EQ(r.end_sample, 10u);
    EXPECT_LE(r.seconds, po.time_limit);
    for (uint32_t p = 0; p < 64; ++p) ASSERT_EQ(film.pixel_count(p), 10u);
}

TEST(Progressive, TheFirstPassRunsEvenWhenTheLimitHasPassedBeforeItStarts) {
    // Start-up (a slow sanitizer build, a loaded machine) may take longer than a short limit
    // before the first pass: the render still gives a 1-spp image, not a black 0-spp one.
    const SceneDescription d = test::hexroom(8, 8, 100, 1);
    const Scene scene = build_scene(d);
    RenderSession session(scene, options_for(Integrator::wavefront, 2));
    Film film = test::film_for(scene);
    double now = 0.0;
    ProgressiveOptions po;
    po.samples = {0, 100};
    po.time_limit = 0.5;
    po.clock = [&now] { return now += 1.0; };  // every reading is a second later
    PassRecorder recorder;
    const ProgressiveResult r = render_progressive(session, film, po, &recorder);
    EXPECT_EQ(r.reason, StopReason::time_limit);
    EXPECT_EQ(r.passes, 1u);
    EXPECT_EQ(r.end_sample, 1u);
    ASSERT_EQ(recorder.passes.size(), 1u);
    EXPECT_EQ(recorder.passes[0].film_spp, 1u);
}

class StopAfterPasses : public PassRecorder {
public:
    std::atomic<bool> stop{false};
    bool pass_done(const Film& film, const PassReport& report) override {
        PassRecorder::pass_done(film, report);
        if (passes.size() == 3) stop = true;  // as a signal handler would, between passes
        return true;
    }
};

TEST(Progressive, AStopRequestEndsTheRenderAtTheNextPassBoundary) {
    const SceneDescription d = test::hexroom(8, 8, 64, 1);
    const Scene scene = build_scene(d);
    RenderSession session(scene, options_for(Integrator::wavefront, 2));
    Film film = test::film_for(scene);
    StopAfterPasses observer;
    ProgressiveOptions po;
    po.samples = {0, 64};
    po.stop = &observer.stop;
    const ProgressiveResult r = render_progressive(session, film, po, &observer);
    EXPECT_EQ(r.reason, StopReason::interrupted);
    EXPECT_EQ(r.passes, 3u);
    EXPECT_EQ(r.end_sample, 4u);  // 1 + 1 + 2
    Film first_four = test::film_for(scene);
    RenderSession(scene, options_for(Integrator::wavefront, 1)).render_samples(first_four, {0, 4});
    EXPECT_TRUE(film == first_four) << "the stopped render holds exactly the first 4 samples";
}

TEST(Progressive, AResumedFilmContinuesTheDoublingFromItsOwnSpp) {
    const SceneDescription d = test::hexroom(8, 8, 40, 2);
    const Scene scene = build_scene(d);
    RenderSession session(scene, options_for(Integrator::wavefront, 2));
    Film film = test::film_for(scene);
    session.render_samples(film, {0, 8});
    ProgressiveOptions po;
    po.samples = {8, 40};
    po.pass_seconds = 1e9;
    PassRecorder recorder;
    render_progressive(session, film, po, &recorder);
    ASSERT_EQ(recorder.passes.size(), 3u);  // 8 -> 16 -> 32 -> 40
    EXPECT_EQ(recorder.passes[0].pass_samples.begin, 8u);
    EXPECT_EQ(recorder.passes[0].film_spp, 16u);
    EXPECT_EQ(recorder.passes[2].film_spp, 40u);
    EXPECT_TRUE(film == test::render_film(d, Integrator::wavefront, 1).film);
}

}  // namespace
}  // namespace wt
