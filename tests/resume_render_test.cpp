// A render stopped at a sample, saved as a checkpoint, read back and continued in another
// session gives the bits of the render that never stopped; raising spp on resume gives the
// bits of a render of the larger spp, for every sampler (none depends on the spp).

#include <gtest/gtest.h>

#include "core/checkpoint/checkpoint.h"
#include "core/scene_file/scene_loader.h"
#include "core/description/scene_hash.h"
#include "core/system/version.h"
#include "kernels/renderer.h"

namespace wt {
namespace {

SceneDescription small_hexroom(int spp) {
    SceneDescription d = load_scene_file(std::string(WT_SCENES_DIR) + "/hexroom.json");
    d.settings.width = 24, d.settings.height = 18, d.settings.spp = spp;
    return d;
}

// An empty film of the render's channels (the splats' with light tracing).
Film empty_film(const SceneDescription& d) {
    return Film(d.settings.width, d.settings.height, film_channels_for({}, light_traces_caustics(d)));
}

Film render_range(const SceneDescription& d, Film film, SampleRange range, int threads) {
    const Scene scene = build_scene(d);
    RenderOptions options;
    options.threads = threads;
    RenderSession session(scene, options);
    session.render_samples(film, range);
    return film;
}

Film through_checkpoint(const SceneDescription& d, const Film& film, SampleRange held) {
    const CheckpointHeader header{program_version(), scene_content_hash(d), held.begin, held.end,
                                  uint32_t(d.settings.spp), image_settings(d.settings)};
    return parse_checkpoint(checkpoint_bytes(header, film), "test.ckpt").film;
}

TEST(ResumeRender, InterruptedAndResumedEqualsUninterrupted) {
    const SceneDescription d = small_hexroom(8);
    const Film whole = render_range(d, empty_film(d), {0, 8}, 2);
    for (uint32_t stop : {1u, 3u, 7u}) {
        const Film before = render_range(d, empty_film(d), {0, stop}, 1);
        EXPECT_FALSE(before == whole);
        const Film resumed = render_range(d, through_checkpoint(d, before, {0, stop}), {stop, 8}, 3);
        EXPECT_TRUE(resumed == whole) << "stopped at sample " << stop;
    }
}

TEST(ResumeRender, RaisingSppGivesTheRenderOfTheLargerSpp) {
    for (SamplerKind sampler : {SamplerKind::stratified, SamplerKind::independent, SamplerKind::sobol}) {
        SceneDescription first = small_hexroom(4), raised = small_hexroom(9);
        first.settings.estimator.sampler = raised.settings.estimator.sampler = sampler;
        const Film finished = render_range(first, empty_film(first), {0, 4}, 2);
        const Film resumed = render_range(raised, through_checkpoint(first, finished, {0, 4}), {4, 9}, 2);
        EXPECT_TRUE(resumed == render_range(raised, empty_film(raised), {0, 9}, 1)) << name_of(sampler);
    }
}

}  // namespace
}  // namespace wt
