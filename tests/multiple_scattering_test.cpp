// Kulla & Conty's multiple-scattering compensation (core/materials/multiple_scattering.h): the
// GGX albedo table against the closed form at alpha 1 and against a quadrature of f that shares
// nothing with the table's sampler; the average as the interpolant's integral; the white furnace
// at 1 with compensation and below it without (both sides); colour growing more saturated with
// roughness as Kulla & Conty's F_ms says; the samplers against their pdfs (chi-square), weights
// equal to f cos / pdf, reciprocity; the principled material's specular lobe; and the exact
// conductor's F_avg.

#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "core/materials/ggx_albedo.h"
#include "core/materials/microfacet_bsdf.h"
#include "core/materials/multiple_scattering.h"
#include "core/materials/rough_conductor.h"
#include "bsdf_helpers.h"
#include "microfacet_checks.h"

namespace wt {
namespace {

using test::Albedo;
using test::direction_at;
using test::Sampled;
using test::sampled_albedo;
using test::sampling_p_value;
using test::sphere_integral;
using test::view;

Material compensated_conductor(float roughness, glm::vec3 f0 = glm::vec3(1.0f)) {
    Material m;
    m.type = MaterialType::rough_conductor;
    m.roughness = roughness;
    m.f0 = f0;
    m.multiple_scattering = true;
    return m;
}

Material compensated_principled(float roughness, glm::vec3 base_color, float metallic) {
    Material m;
    m.type = MaterialType::principled;
    m.roughness = roughness;
    m.base_color = base_color;
    m.metallic = metallic;
    m.multiple_scattering = true;
    return m;
}

// Integral of f cos over the hemisphere by quadrature (f from the BSDF's evaluation, not its sampler).
double quadrature_albedo(const MicrofacetBsdfAtView& bsdf, int channel = 0) {
    return sphere_integral([&](const glm::vec3& wi) { return double(bsdf.f_cos(wi)[channel]); }, 800);
}

// What the table is checked to: its own error (the quadrature over visible normals, the
// interpolation between grid points) plus the reference's (sphere_integral's grid is coarse for
// the sharper lobes).
constexpr double kTableTolerance = 1.5e-3;

TEST(GgxAlbedoTable, GridMatchesTheClosedFormAndAQuadratureOfF) {
    const GgxAlbedoTable& table = ggx_albedo_table();
    constexpr int last_cos = GgxAlbedoTable::kCosines - 1, last_roughness = GgxAlbedoTable::kRoughnesses - 1;
    // At alpha 1 and normal incidence: 1 - ln 2 (tests/microfacet_bsdf_test.cpp derives it).
    EXPECT_NEAR(table.at(last_cos, last_roughness), 1.0 - std::log(2.0), 1e-3);
    // Against the integral of the lobe's f cos, which the table's sampler never evaluates; the
    // sharpest lobes are too narrow for the quadrature's grid.
    for (int j : {10, 20, last_roughness})
        for (int i : {20, 30, 45, last_cos}) {
            const float roughness = float(j) / last_roughness, cos_o = GgxAlbedoTable::cosine_at(i);
            const RoughConductor lobe(ggx_alpha(roughness), ConductorFresnel{glm::vec3(1.0f)});
            const glm::vec3 wo(std::sqrt(1.0f - cos_o * cos_o), 0.0f, cos_o);
            const double e = sphere_integral(
                [&](const glm::vec3& wi) { return wi.z > 0.0f ? double(lobe.f(wo, wi).x) * wi.z : 0.0; }, 800);
            EXPECT_NEAR(table.at(i, j), e, kTableTolerance) << "roughness " << roughness << " cos " << cos_o;
        }
    // The smoothest lobe loses nothing seen away from grazing. At alpha 1 E is least head-on
    // and climbs back towards grazing, where G2 / G1(wo) tends to 1 as Lambda(wo) grows.
    EXPECT_GT(table.at(last_cos / 2, 0), 0.999f);
    EXPECT_GT(table.at(10, last_roughness), table.at(last_cos / 2, last_roughness));
    EXPECT_GT(table.at(last_cos / 2, last_roughness), table.at(last_cos, last_roughness));
}

// Between the grid points the table is read bilinearly: checked against the quadrature of f at
// the cells' centres, where interpolation is furthest from the grid, over the angles a render
// sees (the grid is finest towards grazing, where the smooth lobes' E climbs steeply).
TEST(GgxAlbedoTable, InterpolatesBetweenGridPoints) {
    const GgxAlbedoTable& table = ggx_albedo_table();
    for (float roughness : {0.3f + 0.5f / 31, 0.6f, 1.0f - 0.5f / 31})
        for (float cos_o : {0.05f, 0.2f, 0.5f, 0.8f, 0.97f}) {
            const RoughConductor lobe(ggx_alpha(roughness), ConductorFresnel{glm::vec3(1.0f)});
            const glm::vec3 wo(std::sqrt(1.0f - cos_o * cos_o), 0.0f, cos_o);
            const double e = sphere_integral(
                [&](const glm::vec3& wi) { return wi.z > 0.0f ? double(lobe.f(wo, wi).x) * wi.z : 0.0; }, 800);
            EXPECT_NEAR(table.albedo(cos_o, roughness), e, kTableTolerance) << "roughness " << roughness << " cos " << cos_o;
        }
}

TEST(GgxAlbedoTable, AverageIsTheIntegralOfTheInterpolant) {
    const GgxAlbedoTable& table = ggx_albedo_table();
    for (float roughness : {0.0f, 0.137f, 0.5f, 0.77f, 1.0f}) {
        constexpr int n = 20000;
        double sum = 0.0;
        for (int i = 0; i < n; ++i) {
            const float mu = (float(i) + 0.5f) / n;
            sum += 2.0 * double(table.albedo(mu, roughness)) * mu / n;
        }
        EXPECT_NEAR(table.average(roughness), sum, 1e-5) << roughness;
    }
    // Read between grid points, at the grid points, and clamped outside [0, 1].
    EXPECT_EQ(table.albedo(1.0f, 1.0f), table.at(GgxAlbedoTable::kCosines - 1, GgxAlbedoTable::kRoughnesses - 1));
    EXPECT_EQ(table.albedo(2.0f, 7.0f), table.albedo(1.0f, 1.0f));
    EXPECT_EQ(table.albedo(-1.0f, NAN), table.at(0, 0));
}

// A white metal with compensation reflects everything it receives, at every angle and roughness;
// without it the same metal loses light (microfacet_bsdf_test measures how much).
TEST(MultipleScatteringFurnace, WhiteMetalReflectsOneWithCompensationAndLessWithout) {
    for (const float roughness : {0.1f, 0.3f, 0.6f, 1.0f})
        for (const float theta : {0.0f, 0.7f, 1.3f, 1.5f}) {
            const glm::vec3 wo = direction_at(theta, 0.2);
            const Albedo on = sampled_albedo(view(compensated_conductor(roughness), wo), 40000, 5);
            EXPECT_NEAR(on.mean, 1.0, 4.0 * on.standard_error + kTableTolerance) << roughness << " " << theta;
            if (roughness >= 0.3f) {
                EXPECT_NEAR(quadrature_albedo(view(compensated_conductor(roughness), wo)), 1.0, kTableTolerance);
            }
            Material single = compensated_conductor(roughness);
            single.multiple_scattering = false;
            const Albedo off = sampled_albedo(view(single, wo), 40000, 5);
            if (roughness >= 0.6f) {
                EXPECT_LT(off.mean, 0.95) << roughness << " " << theta;
            }
            EXPECT_LT(off.mean, on.mean) << roughness << " " << theta;
        }
}

// Kulla & Conty's F_ms: light that bounces k times is tinted k times, so a coloured rough metal's
// compensated albedo is its single-scattering albedo plus F_ms (1 - E(mu_o)), per channel, and
// its colour grows more saturated than F's.
TEST(MultipleScatteringFurnace, ColouredMetalGainsFmsTimesWhatSingleScatteringLoses) {
    const glm::vec3 f0(0.95f, 0.64f, 0.54f);  // copper-like
    const float roughness = 0.8f;
    const glm::vec3 wo = direction_at(0.5, 0.0);
    Material single = compensated_conductor(roughness, f0);
    single.multiple_scattering = false;
    const GgxAlbedoTable& table = ggx_albedo_table();
    const float e_o = table.albedo(wo.z, roughness), e_avg = table.average(roughness);
    const glm::vec3 f_avg = schlick_fresnel_average(f0);
    double gained[3];
    for (int c = 0; c < 3; ++c) {
        const double f_ms = double(f_avg[c]) * f_avg[c] * e_avg / (1.0 - double(f_avg[c]) * (1.0 - e_avg));
        const double with = quadrature_albedo(view(compensated_conductor(roughness, f0), wo), c);
        const double without = quadrature_albedo(view(single, wo), c);
        gained[c] = with - without;
        EXPECT_NEAR(gained[c], f_ms * (1.0 - e_o), 1e-3) << c;
    }
    // Red gains a larger share of what it had than blue: more saturated.
    EXPECT_GT(gained[0] / f0[0], gained[2] / f0[2]);
}

// One significance level for the chi-square tests below together (Sidak's correction).
constexpr int kChiSquareTests = 2 * 3 + 2 * 3;
const double kSignificance = 1.0 - std::pow(1.0 - 0.01, 1.0 / kChiSquareTests);

TEST(MultipleScatteringSampling, SamplersMatchTheirPdfsAndWeighFCosOverPdf) {
    uint32_t seed = 300;
    for (const Material& m : {compensated_conductor(0.5f, glm::vec3(0.9f, 0.6f, 0.3f)), compensated_conductor(0.9f),
                              compensated_principled(0.5f, glm::vec3(0.8f, 0.3f, 0.2f), 0.5f),
                              compensated_principled(0.9f, glm::vec3(0.9f), 0.0f)})
        for (float theta : {0.2f, 1.0f, 1.45f}) {
            const MicrofacetBsdfAtView bsdf = view(m, direction_at(theta, 0.7));
            if (m.roughness != 0.5f || theta != 1.0f) {
                const double p = sampling_p_value(
                    [&](float u0, float u1, float u2) {
                        const BsdfSample s = bsdf.sample(u0, u1, u2);
                        return Sampled{s.valid, s.direction};
                    },
                    [&](const glm::vec3& wi) { return double(bsdf.pdf(wi)); }, 200000, seed++);
                EXPECT_GT(p, kSignificance) << int(m.type) << " roughness " << m.roughness << " theta " << theta;
            }
            std::mt19937 rng(seed);
            std::uniform_real_distribution<float> u(0.0f, 1.0f);
            for (int k = 0; k < 200; ++k) {
                const BsdfSample s = bsdf.sample(u(rng), u(rng), u(rng));
                if (!s.valid) continue;
                const glm::vec3 expected = bsdf.f_cos(s.direction) / bsdf.pdf(s.direction);
                for (int c = 0; c < 3; ++c) EXPECT_NEAR(s.weight[c], expected[c], 1e-4f * expected[c] + 1e-6f);
                EXPECT_NEAR(s.pdf, bsdf.pdf(s.direction), 1e-4f * s.pdf);
            }
        }
}

// The added lobe is symmetric, so light paths may sample the compensated BSDFs as camera paths do.
TEST(MultipleScatteringReciprocity, CompensatedLobesAreSymmetric) {
    std::mt19937 rng(8);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    for (const Material& m : {compensated_conductor(0.7f, glm::vec3(0.9f, 0.5f, 0.2f)),
                              compensated_principled(0.6f, glm::vec3(0.7f, 0.4f, 0.9f), 0.3f)})
        for (int k = 0; k < 500; ++k) {
            const glm::vec3 a = direction_at(1.5 * u(rng), 6.2 * u(rng)), b = direction_at(1.5 * u(rng), 6.2 * u(rng));
            const glm::vec3 fab = view(m, a).f_cos(b) / b.z, fba = view(m, b).f_cos(a) / a.z;
            for (int c = 0; c < 3; ++c) EXPECT_NEAR(fab[c], fba[c], 1e-4f * fab[c] + 1e-7f);
        }
}

// The principled material's specular lobe is compensated like the metal: at metallic 1 with a
// white base it is the white metal (albedo 1), and a dielectric gains only the little its 4 %
// specular lobe loses.
TEST(MultipleScatteringFurnace, PrincipledSpecularLobeIsCompensated) {
    for (const float theta : {0.3f, 1.2f}) {
        const glm::vec3 wo = direction_at(theta, 0.4);
        EXPECT_NEAR(quadrature_albedo(view(compensated_principled(0.8f, glm::vec3(1.0f), 1.0f), wo)), 1.0, kTableTolerance);
        Material plastic = compensated_principled(0.8f, glm::vec3(0.5f), 0.0f);
        const double with = quadrature_albedo(view(plastic, wo));
        plastic.multiple_scattering = false;
        const double without = quadrature_albedo(view(plastic, wo));
        EXPECT_GT(with, without);
        EXPECT_LT(with - without, 0.02);
    }
}

TEST(MultipleScatteringFresnel, AveragesOfSchlickAndTheExactTerm) {
    // The quadrature of Schlick's term equals the closed form.
    const glm::vec3 f0(0.9f, 0.5f, 0.04f);
    const glm::vec3 numeric = exact_fresnel_average(ConductorFresnel{f0});
    const glm::vec3 closed = schlick_fresnel_average(f0);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(numeric[c], closed[c], 1e-6f);
    // Gold's complex index: the same integral by Simpson's rule in double on a fine grid.
    const ConductorFresnel gold{glm::vec3(1.0f), glm::vec3(0.143f, 0.374f, 1.442f), glm::vec3(3.983f, 2.385f, 1.603f)};
    const glm::vec3 average = exact_fresnel_average(gold);
    for (int c = 0; c < 3; ++c) {
        constexpr int n = 20000;  // even
        double simpson = 0.0;
        for (int i = 0; i <= n; ++i) {
            const double mu = double(i) / n;
            const double weight = i == 0 || i == n ? 1.0 : (i % 2 ? 4.0 : 2.0);
            simpson += weight * 2.0 * fresnel_conductor_channel(float(mu), gold.eta[c], gold.k[c]) * mu;
        }
        EXPECT_NEAR(average[c], simpson / (3.0 * n), 1e-5) << c;
        EXPECT_LT(average[c], 1.0f);
    }
    // A complex-index conductor uses the average the scene builder stores.
    Material m = compensated_conductor(0.5f);
    m.eta = gold.eta, m.k = gold.k, m.conductor_fresnel_average = average;
    EXPECT_EQ(conductor_fresnel_average(m), average);
    m.eta = glm::vec3(0.0f);
    EXPECT_EQ(conductor_fresnel_average(m), schlick_fresnel_average(m.f0));
}

}  // namespace
}  // namespace wt
