// White furnace: inside a closed room whose every surface has albedo rho and emits Le, the
// radiance everywhere is Le / (1 - rho) (the Neumann series Le * sum rho^k). Any energy lost or
// gained by a BSDF, light sampler, Russian roulette or the scheduling shows up as a bias here.

#include <cmath>

#include <gtest/gtest.h>

#include "render_helpers.h"
#include "statistics.h"
#include "test_scenes.h"
#include "white_furnace_check.h"

namespace wt {
namespace {

struct FurnaceCase {
    const char* name;
    Integrator integrator;
    MaterialType type;
    float rho;
};

class WhiteFurnace : public ::testing::TestWithParam<FurnaceCase> {};

TEST_P(WhiteFurnace, EveryPixelConvergesToLeOverOneMinusRho) {
    const FurnaceCase c = GetParam();
    const float le = 1.0f;
    // Oren-Nayar loses energy by design (its albedo is below rho), so it runs at sigma 0 here;
    // its roughness is tested against quadrature in bsdf_test.
    const SceneDescription d = test::furnace_cube(c.rho, le, c.type, 0.0f);
    const test::RenderedFilm r = test::render_film(d, c.integrator);
    test::expect_white_furnace(r, d, le / (1.0 - c.rho));
}

INSTANTIATE_TEST_SUITE_P(
    Integrators, WhiteFurnace,
    ::testing::Values(FurnaceCase{"wavefront_lambert_half", Integrator::wavefront, MaterialType::lambertian, 0.5f},
                      FurnaceCase{"wavefront_lambert_bright", Integrator::wavefront, MaterialType::lambertian, 0.8f},
                      FurnaceCase{"wavefront_oren_nayar", Integrator::wavefront, MaterialType::oren_nayar, 0.5f},
                      FurnaceCase{"reference_lambert_half", Integrator::reference, MaterialType::lambertian, 0.5f},
                      FurnaceCase{"reference_lambert_bright", Integrator::reference, MaterialType::lambertian, 0.8f}),
    [](const auto& info) { return std::string(info.param.name); });

TEST(WhiteFurnace, BlackRoomShowsOnlyEmission) {
    // rho = 0: the answer is Le exactly, with zero variance, on every sample.
    const SceneDescription d = test::furnace_cube(0.0f, 1.5f);
    const test::RenderedFilm r = test::render_film(d, Integrator::wavefront);
    for (uint32_t p = 0; p < uint32_t(d.settings.width * d.settings.height); ++p) {
        EXPECT_NEAR(r.film.pixel_mean(p).y, 1.5, 1e-6) << "pixel " << p;
    }
}

}  // namespace
}  // namespace wt
