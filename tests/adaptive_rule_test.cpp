// Adaptive sampling's parts on films built by hand: the per-pixel error against its formula,
// the decision points, and the stopping rule (converged pixels stop, an unconverged pixel keeps
// its eight neighbours, stopped pixels count as converged, stops are final), the same on any
// number of threads.

#include <algorithm>
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "core/film/film.h"
#include "core/system/thread_pool.h"
#include "kernels/adaptive/decision_schedule.h"
#include "kernels/adaptive/pixel_error.h"
#include "kernels/adaptive/stopping_rule.h"

namespace wt {
namespace {

AdaptiveSettings with_threshold(float threshold, int min_spp = 16) {
    AdaptiveSettings s;
    s.threshold = threshold;
    s.min_spp = min_spp;
    return s;
}

// `n` samples alternating between `a` and `b` in every channel.
void add_alternating(Film& film, uint32_t pixel, float a, float b, int n) {
    for (int i = 0; i < n; ++i) ASSERT_TRUE(film.add_sample(pixel, glm::vec3(i % 2 ? b : a)));
}

TEST(AdaptivePixelError, MatchesTheFormulaWorkedByHand) {
    Film film(4, 1);
    add_alternating(film, 0, 2.0f, 2.0f, 16);  // constant: no error at all
    EXPECT_EQ(pixel_error(film, 0), 0.0);
    // Samples 0.1 and 0.3: mean 0.2, unbiased variance 0.01 * 16/15, SE per channel sqrt(var / 16);
    // intensity 0.6 < 1 is normalised by its square root.
    add_alternating(film, 1, 0.1f, 0.3f, 16);
    const double variance = 0.01 * 16.0 / 15.0;
    const double se = std::sqrt(variance / 16.0);
    EXPECT_NEAR(pixel_error(film, 1), 3 * se / (1e-4 + std::sqrt(0.6)), 1e-6);
    // Samples 1 and 3: intensity 6 >= 1 is normalised by itself (Cycles' relative error there).
    add_alternating(film, 2, 1.0f, 3.0f, 16);
    const double se2 = std::sqrt(16.0 / 15.0 / 16.0);
    EXPECT_NEAR(pixel_error(film, 2), 3 * se2 / (1e-4 + 6.0), 1e-9);
    // One sample (or none) says nothing of the variance: never converged.
    ASSERT_TRUE(film.add_sample(3, glm::vec3(1.0f)));
    EXPECT_EQ(pixel_error(film, 3), std::numeric_limits<double>::infinity());
}

TEST(AdaptiveSchedule, DecisionsAtTheMinimumThenEverySixteen) {
    const AdaptiveSettings at16 = with_threshold(0.1f, 16), at20 = with_threshold(0.1f, 20), at2 = with_threshold(0.1f, 2);
    for (uint32_t s : {16u, 32u, 48u, 1024u}) EXPECT_TRUE(is_decision_point(at16, s)) << s;
    for (uint32_t s : {0u, 1u, 8u, 15u, 17u, 31u, 33u}) EXPECT_FALSE(is_decision_point(at16, s)) << s;
    EXPECT_TRUE(is_decision_point(at20, 20));
    EXPECT_FALSE(is_decision_point(at20, 16)) << "nothing stops before the minimum";
    EXPECT_TRUE(is_decision_point(at20, 32));
    EXPECT_TRUE(is_decision_point(at2, 2));
    EXPECT_EQ(next_decision_point(at16, 0), 16u);
    EXPECT_EQ(next_decision_point(at16, 15), 16u);
    EXPECT_EQ(next_decision_point(at16, 16), 32u);
    EXPECT_EQ(next_decision_point(at20, 5), 20u);
    EXPECT_EQ(next_decision_point(at20, 20), 32u);
    EXPECT_EQ(next_decision_point(at20, 31), 32u);
    EXPECT_EQ(next_decision_point(at2, 2), 16u);
}

// A 7x5 film: every pixel constant but those listed, which alternate 0 and 10 (far from converged).
Film film_with_noisy(const std::vector<uint32_t>& noisy, int samples = 16) {
    Film film(7, 5);
    for (uint32_t p = 0; p < film.pixel_total(); ++p) {
        const bool is_noisy = std::find(noisy.begin(), noisy.end(), p) != noisy.end();
        add_alternating(film, p, is_noisy ? 0.0f : 0.5f, is_noisy ? 10.0f : 0.5f, samples);
    }
    film.adaptive().stopped_at.assign(film.pixel_total(), AdaptiveState::still_sampling);
    film.adaptive().next_sample = uint32_t(samples);
    return film;
}

bool sampling(const Film& film, int x, int y) { return film.adaptive().sampling(std::size_t(y * film.width() + x)); }

TEST(AdaptiveRule, AnUnconvergedPixelKeepsItsEightNeighboursAndNothingElse) {
    Film film = film_with_noisy({2 * 7 + 3});  // (3, 2)
    EXPECT_EQ(apply_stopping_rule(film, with_threshold(0.05f), 16), 35u - 9u);
    for (int y = 0; y < 5; ++y)
        for (int x = 0; x < 7; ++x) {
            const bool neighbour = std::abs(x - 3) <= 1 && std::abs(y - 2) <= 1;
            EXPECT_EQ(sampling(film, x, y), neighbour) << x << "," << y;
            if (!neighbour) {
                EXPECT_EQ(film.adaptive().stopped_at[std::size_t(y * 7 + x)], 16u);
            }
        }
    // At the corner the box is clipped to the image: four pixels kept.
    Film corner = film_with_noisy({0});
    EXPECT_EQ(apply_stopping_rule(corner, with_threshold(0.05f), 16), 35u - 4u);
    EXPECT_TRUE(sampling(corner, 0, 0) && sampling(corner, 1, 0) && sampling(corner, 0, 1) && sampling(corner, 1, 1));
    EXPECT_FALSE(sampling(corner, 2, 0));
    EXPECT_FALSE(sampling(corner, 0, 2));
}

TEST(AdaptiveRule, TheThresholdDecides) {
    // The same noisy pixel converges under a threshold above its error, and then nothing is kept.
    Film film = film_with_noisy({2 * 7 + 3});
    const double error = pixel_error(film, 2 * 7 + 3);
    EXPECT_GT(error, 0.05);
    Film loose = film_with_noisy({2 * 7 + 3});
    EXPECT_EQ(apply_stopping_rule(loose, with_threshold(float(error) * 1.01f), 16), 35u);
    EXPECT_EQ(apply_stopping_rule(film, with_threshold(float(error) * 0.99f), 16), 26u);
}

TEST(AdaptiveRule, StopsAreFinalAndStoppedPixelsCountAsConverged) {
    Film film = film_with_noisy({2 * 7 + 3});
    // The noisy pixel was stopped at an earlier decision (its film is what it was then): it no
    // longer holds its neighbours, and it stays stopped at its own sample.
    film.adaptive().stopped_at[2 * 7 + 3] = 8;
    EXPECT_EQ(apply_stopping_rule(film, with_threshold(0.05f), 16), 34u);
    EXPECT_EQ(film.adaptive().stopped_at[2 * 7 + 3], 8u);
    EXPECT_EQ(film.adaptive().stopped_at[2 * 7 + 4], 16u);
    // A second decision stops nothing more and moves no stop.
    const AdaptiveState before = film.adaptive();
    EXPECT_EQ(apply_stopping_rule(film, with_threshold(0.05f), 32), 0u);
    EXPECT_TRUE(film.adaptive() == before);
}

TEST(AdaptiveRule, APixelWithOneSampleNeverConverges) {
    // As after dropped non-finite samples: one valid sample gives no variance, so (3, 1) and
    // its neighbours are kept where the same film with 16 samples there would stop everywhere.
    Film one(7, 5), all(7, 5);
    for (uint32_t p = 0; p < one.pixel_total(); ++p) {
        add_alternating(one, p, 0.5f, 0.5f, p == 10 ? 1 : 16);
        add_alternating(all, p, 0.5f, 0.5f, 16);
    }
    for (Film* f : {&one, &all}) f->adaptive().stopped_at.assign(f->pixel_total(), AdaptiveState::still_sampling);
    EXPECT_EQ(apply_stopping_rule(one, with_threshold(0.05f), 16), 35u - 9u);
    EXPECT_TRUE(sampling(one, 3, 1));
    EXPECT_EQ(apply_stopping_rule(all, with_threshold(0.05f), 16), 35u);
}

TEST(AdaptiveRule, RefusesAStateOfAnotherSize) {
    Film film(3, 3);
    film.adaptive().stopped_at.assign(4, AdaptiveState::still_sampling);
    EXPECT_THROW(apply_stopping_rule(film, with_threshold(0.05f), 16), std::invalid_argument);
}

// The threaded rule (rows shared out over a pool) is the serial rule, bit for bit.
TEST(AdaptiveDeterminism, TheRuleOnThreadsEqualsTheRuleOnOne) {
    Film film(61, 37);
    uint64_t state = 5;
    for (uint32_t p = 0; p < film.pixel_total(); ++p)
        for (int i = 0; i < 16; ++i) {
            state = state * 6364136223846793005ull + 1442695040888963407ull;
            const float noise = float(state >> 40) / float(1 << 24) * (p % 5 == 0 ? 3.0f : 0.02f);
            ASSERT_TRUE(film.add_sample(p, glm::vec3(0.5f + noise)));
        }
    film.adaptive().stopped_at.assign(film.pixel_total(), AdaptiveState::still_sampling);
    Film threaded = film;
    const uint32_t serial_stops = apply_stopping_rule(film, with_threshold(0.05f), 16);
    ThreadPool pool(3);
    EXPECT_EQ(apply_stopping_rule(threaded, with_threshold(0.05f), 16, &pool), serial_stops);
    EXPECT_TRUE(threaded.adaptive() == film.adaptive());
    EXPECT_GT(serial_stops, 0u);
    EXPECT_LT(serial_stops, uint32_t(film.pixel_total()));
}

}  // namespace
}  // namespace wt
