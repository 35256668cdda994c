// Photons (kernels/photons) against a caustic seen through a mirror whose answer is known in
// closed form (mirror_caustic.h: the floor's irradiance from the light's mirror image, seen in a
// wall mirror), and against the camera paths' own estimate of the same paths, which is unbiased
// and far noisier.

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "kernels/photons/photon_radius.h"
#include "mirror_caustic.h"
#include "render_helpers.h"

namespace wt {
namespace {

using test::WallMirrorCaustic;

constexpr int kBlock = 6;   // pixels per block side
constexpr int kSub = 4;     // kSub x kSub points per pixel for the analytic mean
constexpr int kSeeds = 12;
// Two-sided Student-t quantile for 1e-4 per block (about a dozen blocks: 1e-3 for the test) with
// kSeeds - 1 = 11 degrees of freedom.
constexpr double kT = 5.45;
constexpr float kRadius = 0.2f;  // r_0 on a floor whose irradiance varies over about a unit

struct Block {
    int x0, y0;
    double analytic = 0.0;  // the mean radiance over the block's pixels
    double bias = 0.0;      // the photons' expected blur of it at the mean r_s^2 (leading order)
    std::vector<double> rendered[2];  // per seed: photons, path
};

// The blocks whose every point sees the floor through the wall, with their analytic means.
std::vector<Block> analytic_blocks(const SceneDescription& d, double mean_radius_squared) {
    std::vector<Block> blocks;
    for (int by = 0; by < d.settings.height; by += kBlock)
        for (int bx = 0; bx < d.settings.width; bx += kBlock) {
            Block b{bx, by, 0.0, 0.0, {}};
            bool usable = true;
            for (int j = 0; j < kBlock * kBlock * kSub * kSub && usable; ++j) {
                const int pixel = j / (kSub * kSub), sub = j % (kSub * kSub);
                const auto p = WallMirrorCaustic::floor_point(d, bx + pixel % kBlock + (sub % kSub + 0.5) / kSub,
                                                              by + pixel / kBlock + (sub / kSub + 0.5) / kSub);
                usable = p.has_value();
                if (!usable) break;
                b.analytic += WallMirrorCaustic::radiance(*p);
                b.bias += WallMirrorCaustic::radiance_blur(*p, mean_radius_squared);
            }
            if (!usable) continue;
            b.analytic /= double(kBlock * kBlock * kSub * kSub);
            b.bias /= double(kBlock * kBlock * kSub * kSub);
            blocks.push_back(b);
        }
    return blocks;
}

double mean_radius_squared(double r0, int spp) {
    PhotonRadiusSchedule schedule(r0);
    double sum = 0.0;
    for (int s = 0; s < spp; ++s) sum += schedule.squared(uint32_t(s));
    return sum / spp;
}

struct SeedStats {
    double mean, standard_error;
};
SeedStats stats(const std::vector<double>& v) {
    double mean = 0.0, var = 0.0;
    for (double x : v) mean += x / double(v.size());
    for (double x : v) var += (x - mean) * (x - mean) / double(v.size() - 1);
    return {mean, std::sqrt(var / double(v.size()))};
}

void render_blocks(std::vector<Block>& blocks, int spp, CausticPaths caustics, int k) {
    for (int s = 0; s < kSeeds; ++s) {
        SceneDescription d = WallMirrorCaustic::scene(spp, uint64_t(1000 + s), caustics);
        d.settings.estimator.light_paths_per_pixel = 16.0f;
        d.settings.estimator.photon_radius = kRadius;
        const test::RenderedFilm r = test::render_film(d, Integrator::wavefront, 2);
        for (Block& b : blocks) {
            double sum = 0.0;
            for (int y = b.y0; y < b.y0 + kBlock; ++y)
                for (int x = b.x0; x < b.x0 + kBlock; ++x) sum += r.film.pixel_mean(uint32_t(y * d.settings.width + x)).y;
            b.rendered[k].push_back(sum / (kBlock * kBlock));
        }
    }
}

// The photons' estimate converges to the analytic radiance (within the seeds' Student-t bound
// and twice the leading-order blur at the mean radius, which the check below keeps small beside
// the value), and the camera paths alone converge to the same answer with several times the
// spread at the same spp: the caustic is seen only through the wall mirror, where light tracing
// connects nothing.
TEST(Photons, CausticSeenThroughAMirrorMatchesTheAnalyticAnswerAndIsLessNoisyThanPathTracing) {
    const int spp = 16;
    const SceneDescription d0 = WallMirrorCaustic::scene(spp, 0, CausticPaths::photons);
    std::vector<Block> blocks = analytic_blocks(d0, mean_radius_squared(kRadius, spp));
    ASSERT_GE(blocks.size(), 6u) << "the view must hold blocks of floor seen in the wall";
    render_blocks(blocks, spp, CausticPaths::photons, 0);
    render_blocks(blocks, spp, CausticPaths::path, 1);
    for (const Block& b : blocks) {
        const SeedStats photons = stats(b.rendered[0]), path = stats(b.rendered[1]);
        const std::string where = "block at pixel (" + std::to_string(b.x0) + ", " + std::to_string(b.y0) + ")";
        EXPECT_LT(std::fabs(b.bias), 0.01 * b.analytic) << where << ": the bias allowance must stay small";
        EXPECT_NEAR(photons.mean, b.analytic, kT * photons.standard_error + 2.0 * std::fabs(b.bias) + 1e-3 * b.analytic)
            << where << ", photons (relative error " << photons.mean / b.analytic - 1.0 << ")";
        EXPECT_LT(kT * photons.standard_error, 0.1 * b.analytic) << where << ": resolution of the photons' check";
        EXPECT_GT(path.standard_error, 3.0 * photons.standard_error)
            << where << ": photons " << photons.standard_error << ", path " << path.standard_error;
    }
    // The camera paths find the light's image by chance, a few times per block and seed: their
    // per-block means are too skewed for a t bound, so theirs is the mean over all the blocks.
    std::vector<double> pooled(kSeeds, 0.0);
    double analytic = 0.0;
    for (const Block& b : blocks) {
        analytic += b.analytic / double(blocks.size());
        for (int s = 0; s < kSeeds; ++s) pooled[std::size_t(s)] += b.rendered[1][std::size_t(s)] / double(blocks.size());
    }
    const SeedStats path = stats(pooled);
    EXPECT_NEAR(path.mean, analytic, kT * path.standard_error + 1e-3 * analytic)
        << "path over all blocks (relative error " << path.mean / analytic - 1.0 << ")";
}

}  // namespace
}  // namespace wt
