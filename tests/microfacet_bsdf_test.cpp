// The GGX materials against their definitions: the distribution's normalisations, each
// sampler against its pdf (chi-square over the whole sphere), weights equal to f cos / pdf,
// reciprocity, energy (white furnace), the conductor's exact Fresnel against complex
// arithmetic, the smooth limits, and the extremes.

#include <algorithm>
#include <cmath>
#include <complex>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "core/materials/bsdf.h"
#include "core/materials/microfacet_bsdf.h"
#include "core/materials/microfacet_material.h"
#include "bsdf_helpers.h"
#include "microfacet_checks.h"
#include "statistics.h"

namespace wt {
namespace {

using test::direction_at;
using test::Sampled;
using test::sampled_albedo;
using test::sampling_p_value;
using test::sphere_integral;
using test::view;
using test::Albedo;

const glm::vec3 kUp(0, 0, 1);

Material conductor(float roughness, glm::vec3 f0 = glm::vec3(1.0f)) {
    Material m;
    m.type = MaterialType::rough_conductor;
    m.roughness = roughness;
    m.f0 = f0;
    return m;
}

Material rough_glass(float roughness, float ior) {
    Material m;
    m.type = MaterialType::rough_glass;
    m.roughness = roughness;
    m.ior = ior;
    return m;
}

TEST(Ggx, DistributionAndVisibleNormalsAreNormalised) {
    for (float alpha : {0.1f, 0.5f, 1.0f}) {
        const GgxDistribution ggx(alpha);
        const int n = alpha < 0.2f ? 1200 : 400;
        EXPECT_NEAR(sphere_integral([&](const glm::vec3& h) { return double(ggx.d(h)) * std::max(0.0f, h.z); }, n), 1.0, 2e-3)
            << alpha;
        for (float theta : {0.0f, 0.8f, 1.5f}) {
            const glm::vec3 wo = direction_at(theta, 0.4);
            EXPECT_NEAR(sphere_integral([&](const glm::vec3& h) { return double(ggx.visible_normal_pdf(wo, h)); }, n), 1.0,
                        3e-3)
                << alpha << " " << theta;
        }
    }
}

TEST(Ggx, MaskingIsOneAtNormalIncidenceAndFallsTowardsGrazing) {
    const GgxDistribution ggx(0.5f);
    EXPECT_FLOAT_EQ(ggx.g1(kUp), 1.0f);
    EXPECT_GT(ggx.g1(direction_at(0.5, 0)), ggx.g1(direction_at(1.2, 0)));
    EXPECT_EQ(ggx.g1(glm::vec3(1, 0, 0)), 0.0f);
    // Height-correlated: never more masking than the two separately (G2 >= G1 G1).
    const glm::vec3 a = direction_at(1.0, 0), b = direction_at(1.3, 2);
    EXPECT_GE(ggx.g2(a, b), ggx.g1(a) * ggx.g1(b));
    EXPECT_LE(ggx.g2(a, b), std::min(ggx.g1(a), ggx.g1(b)));
}

// One significance level for all the chi-square tests below together (Sidak's correction).
constexpr int kChiSquareTests = 2 * 3 * 2 + 2 * 3 * 3;
const double kSignificance = 1.0 - std::pow(1.0 - 0.01, 1.0 / kChiSquareTests);

TEST(MicrofacetSampling, ConductorMatchesItsPdf) {
    uint32_t seed = 1;
    for (float roughness : {0.5f, 0.9f})
        for (float theta : {0.2f, 1.0f, 1.45f}) {
            const MicrofacetBsdfAtView bsdf = view(conductor(roughness), direction_at(theta, 0.7));
            const double p = sampling_p_value(
                [&](float u0, float u1, float u2) {
                    const BsdfSample s = bsdf.sample(u0, u1, u2);
                    return Sampled{s.valid, s.direction};
                },
                [&](const glm::vec3& wi) { return double(bsdf.pdf(wi)); }, 200000, seed++);
            EXPECT_GT(p, kSignificance) << "roughness " << roughness << " theta " << theta;
        }
}

TEST(MicrofacetSampling, RoughGlassMatchesItsPdfOnBothSides) {
    uint32_t seed = 100;
    for (float roughness : {0.5f, 0.9f})
        for (float theta : {0.2f, 1.0f, 1.45f})
            for (int side = 0; side < 3; ++side) {
                // Entering ior 1.5, leaving it (total internal reflection past 42 degrees), entering 1.33.
                const float ior = side == 2 ? 1.33f : 1.5f;
                const MicrofacetBsdfAtView bsdf = view(rough_glass(roughness, ior), direction_at(theta, 0.7), side != 1);
                const double p = sampling_p_value(
                    [&](float u0, float u1, float u2) {
                        const BsdfSample s = bsdf.sample(u0, u1, u2);
                        return Sampled{s.valid, s.direction};
                    },
                    [&](const glm::vec3& wi) { return double(bsdf.pdf(wi)); }, 200000, seed++);
                EXPECT_GT(p, kSignificance) << "roughness " << roughness << " theta " << theta << " side " << side;
            }
}

TEST(MicrofacetSampling, WeightIsFCosOverPdf) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    for (const Material& m : {conductor(0.1f, glm::vec3(0.9f, 0.6f, 0.3f)), conductor(0.6f, glm::vec3(0.2f)),
                              rough_glass(0.1f, 1.5f), rough_glass(0.6f, 1.5f), rough_glass(0.4f, 4.0f)})
        for (bool front : {true, false})
            for (int k = 0; k < 300; ++k) {
                // At roughness 0.05 (alpha 0.0025) the half vector recomputed from the rounded
                // directions is off by ~1e-4 rad, enough to move D by a few percent (ggx.h).
                const float tolerance = m.roughness < 0.2f ? 0.02f : 2e-3f;
                const MicrofacetBsdfAtView bsdf = view(m, direction_at(1.5 * u(rng), 6.2 * u(rng)), front);
                const BsdfSample s = bsdf.sample(u(rng), u(rng), u(rng));
                if (!s.valid) continue;
                EXPECT_NEAR(s.pdf, bsdf.pdf(s.direction), tolerance * s.pdf);
                const glm::vec3 expected = bsdf.f_cos(s.direction) / s.pdf;
                for (int c = 0; c < 3; ++c) EXPECT_NEAR(s.weight[c], expected[c], tolerance * expected[c] + 1e-6f);
            }
}

TEST(MicrofacetReciprocity, ConductorAndReflectionAreSymmetric) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    for (const Material& m : {conductor(0.3f, glm::vec3(0.9f, 0.5f, 0.2f)), rough_glass(0.3f, 1.5f)})
        for (int k = 0; k < 500; ++k) {
            const glm::vec3 a = direction_at(1.5 * u(rng), 6.2 * u(rng)), b = direction_at(1.5 * u(rng), 6.2 * u(rng));
            const glm::vec3 fab = view(m, a).f_cos(b) / b.z, fba = view(m, b).f_cos(a) / a.z;
            for (int c = 0; c < 3; ++c) EXPECT_NEAR(fab[c], fba[c], 1e-4f * fab[c] + 1e-7f);
        }
}

// Without radiance's eta^2 (rough_dielectric.h), f(wo, wi) / n_wi^2 = f(wi, wo) / n_wo^2.
TEST(MicrofacetReciprocity, RefractionFollowsTheEtaSquaredRule) {
    std::mt19937 rng(4);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    const float ior = 1.5f;
    const Material m = rough_glass(0.4f, ior);
    int compared = 0;
    for (int k = 0; k < 500; ++k) {
        const glm::vec3 outside = direction_at(1.5 * u(rng), 6.2 * u(rng));
        const glm::vec3 inside = direction_at(M_PI - 1.5 * u(rng), 6.2 * u(rng));
        const float f_out_in = view(m, outside, true).f_cos(inside).x / std::abs(inside.z);   // wo outside, wi inside
        const float f_in_out = view(m, inside, false).f_cos(outside).x / outside.z;          // wo inside, wi outside
        // Tiny values (grazing, near total internal reflection) carry the half vector's rounding.
        if (!(f_in_out > 1e-3f)) continue;
        EXPECT_NEAR(f_out_in / (ior * ior), f_in_out, 1e-3f * f_in_out);
        ++compared;
    }
    EXPECT_GT(compared, 100);
}

TEST(MicrofacetFurnace, EnergyNeverAboveOneAndTheKnownLossAtRoughnessOne) {
    for (const float theta : {0.0f, 0.7f, 1.3f, 1.55f}) {
        const glm::vec3 wo = direction_at(theta, 0.2);
        double previous = 2.0;
        for (const float roughness : {0.03f, 0.3f, 0.6f, 1.0f}) {
            const Albedo a = sampled_albedo(view(conductor(roughness), wo), 40000, 11);
            // Every weight is F G2 / G1 <= 1, so the mean cannot exceed 1 at all.
            EXPECT_LE(a.mean, 1.0);
            // Agrees with the integral of f cos (quadrature, independent of the sampler; the
            // sharpest lobe is too narrow for the grid).
            if (roughness > 0.1f) {
                const MicrofacetBsdfAtView bsdf = view(conductor(roughness), wo);
                const double quadrature = sphere_integral([&](const glm::vec3& wi) { return double(bsdf.f_cos(wi).x); }, 800);
                EXPECT_NEAR(a.mean, quadrature, 4.0 * a.standard_error + 3e-3) << roughness << " " << theta;
            }
            // Single scattering loses more the rougher the surface (away from grazing, where
            // G2 / G1 tends to 1 and the sharp lobes are the ones masked).
            if (theta < 1.5f) {
                EXPECT_LT(a.mean, previous + 4.0 * a.standard_error);
            }
            previous = a.mean;
            if (roughness == 0.03f && theta < 1.0f) {
                EXPECT_GT(a.mean, 0.99);
            }
            // Kulla & Conty 2017: at alpha 1 single-scattering GGX loses a good part of the
            // light, most at grazing (about two thirds there), which their compensation restores.
            if (roughness == 1.0f && theta < 1.5f) {
                EXPECT_LT(a.mean, theta < 1.0f ? 0.9 : 0.6) << theta;
                EXPECT_GT(a.mean, 0.25) << theta;
            }
            // At alpha 1 D is uniform (1 / pi) and at normal incidence G1 = 1, so the albedo is
            // the integral of G2 over the reflected visible normals: 1 - ln 2 in closed form.
            if (roughness == 1.0f && theta == 0.0f) {
                EXPECT_NEAR(a.mean, 1.0 - std::log(2.0), 4.0 * a.standard_error);
            }
        }
    }
    for (const float ior : {1.33f, 1.5f, 4.0f})
        for (const bool front : {true, false}) {
            const Albedo a = sampled_albedo(view(rough_glass(0.5f, ior), direction_at(0.9, 0.0), front), 40000, 12);
            EXPECT_LE(a.mean, 1.0);
            EXPECT_GT(a.mean, 0.8);
        }
}

TEST(ConductorFresnel, ExactFormulaMatchesComplexArithmetic) {
    // Gold-like and aluminium-like indices, and a weak absorber.
    for (const auto& [eta, k] : std::vector<std::pair<float, float>>{{0.18f, 3.4f}, {1.2f, 7.0f}, {1.5f, 0.01f}, {2.5f, 1.0f}})
        for (double theta = 0.0; theta < 1.5707; theta += 0.05) {
            const std::complex<double> n(eta, k);
            const double c = std::cos(theta), s2 = 1.0 - c * c;
            const std::complex<double> ct = std::sqrt(1.0 - s2 / (n * n));
            const double rs = std::norm((c - n * ct) / (c + n * ct));
            const double rp = std::norm((ct - n * c) / (ct + n * c));
            EXPECT_NEAR(fresnel_conductor_channel(float(c), eta, k), 0.5 * (rs + rp), 2e-5) << eta << " " << k << " " << theta;
        }
    EXPECT_FLOAT_EQ(fresnel_conductor_channel(0.0f, 1.0f, 0.0f), 1.0f);  // the 0/0 at grazing
    EXPECT_NEAR(fresnel_conductor_channel(1.0f, 1.0f, 0.0f), 0.0f, 1e-7f);
}

TEST(MicrofacetSmoothLimit, RoughnessZeroLoadsAsTheSmoothMaterials) {
    EXPECT_EQ(conductor_type(0.0f), MaterialType::conductor);
    EXPECT_EQ(conductor_type(0.01f), MaterialType::rough_conductor);
    EXPECT_EQ(dielectric_type(0.0f, 1.5f), MaterialType::glass);
    EXPECT_EQ(dielectric_type(0.5f, 1.0f), MaterialType::glass);  // index-matched: invisible
    EXPECT_EQ(dielectric_type(0.5f, 1.5f), MaterialType::rough_glass);
}

TEST(MicrofacetSmoothLimit, WhiteSmoothConductorIsTheMirrorBitForBit) {
    Material mirror;
    mirror.type = MaterialType::mirror;
    Material smooth = conductor(0.0f);
    smooth.type = MaterialType::conductor;
    Material tinted = smooth;
    tinted.f0 = glm::vec3(0.9f, 0.6f, 0.3f);
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    for (int k = 0; k < 1000; ++k) {
        const glm::vec3 d = -direction_at(1.57 * u(rng), 6.28 * u(rng));
        const BsdfSample a = sample_bsdf(smooth, kUp, d, u(rng), u(rng), u(rng));
        const BsdfSample b = sample_bsdf(mirror, kUp, d, 0.3f, 0.6f, 0.1f);
        EXPECT_EQ(a.direction, b.direction);
        EXPECT_EQ(a.weight, b.weight);
        EXPECT_TRUE(a.specular && a.valid);
        // Tinted, Schlick's curve: F0 at normal incidence, towards white at grazing.
        const BsdfSample t = sample_bsdf(tinted, kUp, d, 0.3f, 0.6f, 0.1f);
        EXPECT_EQ(t.direction, b.direction);
        EXPECT_EQ(t.weight, schlick_conductor(tinted.f0, -d.z));
    }
}

// At the smallest alpha the rough lobes sample (almost) the smooth directions with the smooth
// weights: the mirror's, and the glass's reflect-or-refract choice for the same u_choice.
TEST(MicrofacetSmoothLimit, SmallestRoughnessSamplesNearTheSmoothDirections) {
    Material glass;
    glass.type = MaterialType::glass;
    glass.ior = 1.5f;
    std::mt19937 rng(6);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    int same_choice = 0, near_mirror = 0;
    const int n = 2000;
    for (int k = 0; k < n; ++k) {
        const glm::vec3 d = -direction_at(1.4 * u(rng), 6.28 * u(rng));
        const bool front = u(rng) < 0.5f;
        const glm::vec3 ng = front ? kUp : -kUp;
        const glm::vec3 dd = front ? d : -d;  // arriving from outside or from inside
        const float u0 = u(rng), u1 = u(rng), uc = u(rng);
        const BsdfSample smooth = sample_bsdf(glass, ng, dd, u0, u1, uc);
        const BsdfSample rough = sample_bsdf(rough_glass(1e-6f, 1.5f), ng, dd, u0, u1, uc);
        ASSERT_TRUE(rough.valid);
        if (rough.transmitted == smooth.transmitted) {
            ++same_choice;
            EXPECT_GT(glm::dot(rough.direction, smooth.direction), std::cos(0.2f));
        }
        EXPECT_NEAR(rough.weight.x, 1.0f, 0.02f);
        const BsdfSample metal = sample_bsdf(conductor(1e-6f), kUp, d, u0, u1, uc);
        ASSERT_TRUE(metal.valid);
        if (glm::dot(metal.direction, glm::normalize(reflect(d, kUp))) > std::cos(0.01f)) ++near_mirror;
        EXPECT_NEAR(metal.weight.x, 1.0f, 0.02f);
    }
    EXPECT_GT(same_choice, n * 98 / 100);  // differs only where u_choice falls between R(h) and R(n)
    EXPECT_GT(near_mirror, n * 95 / 100);  // GGX's long tail reaches further, rarely
}

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

TEST(MicrofacetExtremes, NoNanOrInfinityAnywhere) {
    std::vector<Material> materials;
    for (float r : {0.0f, 1e-4f, 0.5f, 1.0f}) {
        for (glm::vec3 f0 : {glm::vec3(0.0f), glm::vec3(1.0f)}) materials.push_back(conductor(r, f0));
        Material complex_index = conductor(r);
        complex_index.eta = glm::vec3(0.2f, 1.0f, 3.0f);
        complex_index.k = glm::vec3(3.0f, 0.0f, 0.5f);
        materials.push_back(complex_index);
        for (float ior : {1.0f, 1.0001f, 1.5f, 4.0f}) materials.push_back(rough_glass(r, ior));
    }
    const std::vector<float> thetas = {0.0f, 0.5f, 1.5f, 1.5707f, 1.57079632f};
    std::mt19937 rng(8);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    for (const Material& m : materials)
        for (float theta : thetas)
            for (bool front : {true, false})
                for (FresnelModel fresnel : {FresnelModel::schlick, FresnelModel::exact}) {
                    const glm::vec3 wo = direction_at(theta, 1.0);
                    const MicrofacetBsdfAtView bsdf = view(m, wo, front, fresnel);
                    for (int k = 0; k < 50; ++k) {
                        const BsdfSample s = bsdf.sample(u(rng), u(rng), u(rng));
                        if (s.valid) {
                            EXPECT_TRUE(finite(s.weight) && finite(s.direction)) << int(m.type) << " " << m.roughness;
                            EXPECT_TRUE(s.pdf > 0.0f && std::isfinite(s.pdf));
                            EXPECT_LE(s.weight.x, 1.0f + 1e-5f);
                        }
                        const glm::vec3 wi = direction_at(3.14159 * u(rng), 6.28 * u(rng));
                        EXPECT_TRUE(finite(bsdf.f_cos(wi)));
                        EXPECT_TRUE(std::isfinite(bsdf.pdf(wi)) && bsdf.pdf(wi) >= 0.0f);
                        // At the exact mirror and straight-through directions too.
                        for (const glm::vec3& special : {glm::vec3(-wo.x, -wo.y, wo.z), -wo}) {
                            EXPECT_TRUE(finite(bsdf.f_cos(special)));
                            EXPECT_TRUE(std::isfinite(bsdf.pdf(special)));
                        }
                    }
                }
}

}  // namespace
}  // namespace wt
