// The trade tool's conclusions: the error-against-time fits on exact synthetic data, time to
// an error, the Pareto front, and the configurations built from the knob table.

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "tools/tradeoff/tradeoff_fit.h"
#include "tools/tradeoff/tradeoff_knobs.h"
#include "tools/tradeoff/tradeoff_sweep.h"

namespace wt {
namespace {

std::vector<SampledError> model(double floor, double variance) {
    std::vector<SampledError> points;
    for (double spp : {4.0, 16.0, 64.0, 256.0}) points.push_back({spp, floor + variance / spp});
    return points;
}

TEST(ErrorFit, UnbiasedEstimatorFallsAsTheInverseSquareRootOfSpp) {
    const ErrorFit fit = fit_error_against_spp(model(0.0, 0.5));
    EXPECT_NEAR(fit.slope, -0.5, 1e-12);
    EXPECT_NEAR(fit.c, std::sqrt(0.5), 1e-12);  // RMSE = sqrt(0.5 / spp)
    EXPECT_NEAR(fit.floor, 0.0, 1e-15);
    EXPECT_NEAR(fit.variance, 0.5, 1e-12);
    EXPECT_NEAR(spp_to_reach(fit, 0.05), 200.0, 1e-9);
}

TEST(ErrorFit, BiasedEstimatorShowsItsFloor) {
    const ErrorFit fit = fit_error_against_spp(model(1e-3, 0.5));
    EXPECT_NEAR(fit.floor, 1e-3, 1e-12);
    EXPECT_NEAR(fit.variance, 0.5, 1e-10);
    EXPECT_GT(fit.slope, -0.5);  // flattening towards the floor
    EXPECT_NEAR(spp_to_reach(fit, 0.05), 0.5 / (0.0025 - 0.001), 1e-6);
    EXPECT_EQ(spp_to_reach(fit, 0.03), std::numeric_limits<double>::infinity());  // 0.03^2 < floor
    // The same floor is not invented for the unbiased one, nor a negative one kept.
    const ErrorFit noisy = fit_error_against_spp({{1.0, 0.0100}, {4.0, 0.0024}, {16.0, 0.0006}});
    EXPECT_EQ(noisy.floor, 0.0);
    EXPECT_GT(noisy.variance, 0.0);
}

TEST(ErrorFit, ErrorThatDoesNotFallHasNoSppToTarget) {
    const ErrorFit fit = fit_error_against_spp({{1.0, 0.01}, {4.0, 0.02}});
    EXPECT_GT(fit.slope, 0.0);
    EXPECT_TRUE(std::isnan(spp_to_reach(fit, 0.2)));  // above the fitted floor, but the variance term is negative
}

TEST(ErrorFit, RefusesTooFewPoints) {
    EXPECT_THROW(fit_error_against_spp({{1.0, 0.01}}), std::invalid_argument);
    EXPECT_THROW(fit_error_against_spp({{1.0, 0.01}, {1.0, 0.02}}), std::invalid_argument);
    EXPECT_THROW(fit_error_against_spp({{1.0, 0.0}, {2.0, 0.02}}), std::invalid_argument);
}

TEST(ParetoFront, KeepsOnlyUndominatedPoints) {
    const std::vector<TimedError> points = {
        {1.0, 0.50},  // fastest: on the front
        {2.0, 0.30},  // on
        {2.0, 0.40},  // as slow as the one above and worse: off
        {3.0, 0.35},  // slower and worse than (2, 0.30): off
        {4.0, 0.10},  // on
        {4.0, 0.10},  // a tie dominates nobody: both on
    };
    EXPECT_EQ(pareto_front(points), (std::vector<bool>{true, true, false, false, true, true}));
}

TEST(TradeoffConfigurations, BaseFirstThenEachValueButTheBase) {
    RenderSettings base;
    base.shadow_rays = 3;
    const std::vector<const Knob*> knobs = {&tradeoff_knob("shadow_rays"), &tradeoff_knob("fresnel")};
    const std::vector<Configuration> c = tradeoff_configurations(base, knobs);
    ASSERT_EQ(c.size(), 1u + 4u + 1u);  // shadow rays 1, 2, 4, 8 (3 is the base's); fresnel exact
    EXPECT_EQ(c[0].name, "base");
    EXPECT_EQ(c[1].name, "shadow_rays=1");
    EXPECT_EQ(c[1].settings.shadow_rays, 1);
    EXPECT_EQ(c[4].settings.shadow_rays, 8);
    EXPECT_FALSE(c[4].can_bias);
    EXPECT_EQ(c[5].name, "fresnel=exact");
    EXPECT_EQ(c[5].settings.accuracy.fresnel, FresnelModel::exact);
    EXPECT_EQ(c[5].settings.shadow_rays, 3);  // one knob at a time
    EXPECT_TRUE(c[5].can_bias);
}

TEST(TradeoffConfigurations, EveryKnobValueAppliesAndReadsBack) {
    for (const Knob& k : tradeoff_knobs())
        for (const char* v : k.values) {
            RenderSettings s;
            k.apply(s, v);
            EXPECT_EQ(k.current(s), v) << k.name;
        }
}

TEST(TradeoffConfigurations, UnknownKnobNamesTheKnownOnes) {
    try {
        tradeoff_knob("spp_magic");
        FAIL();
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("'spp_magic'"), std::string::npos);
        EXPECT_NE(std::string(e.what()).find("shadow_rays"), std::string::npos);
    }
}

}  // namespace
}  // namespace wt
