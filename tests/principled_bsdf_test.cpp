// glTF's metallic-roughness material (core/materials/principled.h) against its definition: f
// against the specification's formula written out independently, the lobe-mixture sampler
// against its pdf (chi-square), weights equal to f cos / pdf, reciprocity, the pdf's integral,
// energy (white furnace, and the specification's known excess at grazing views), metallic 0
// roughness 1 as Lambert plus the specular lobe, metallic 1 as the conductor (the mirror at
// roughness 0), and no NaN at the extremes.

#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "core/materials/bsdf.h"
#include "core/materials/microfacet_bsdf.h"
#include "core/materials/microfacet_material.h"
#include "bsdf_helpers.h"
#include "microfacet_checks.h"

namespace wt {
namespace {

using test::Albedo;
using test::direction_at;
using test::principled;
using test::Sampled;
using test::sampled_albedo;
using test::sampling_p_value;
using test::sphere_integral;
using test::view;

const glm::vec3 kUp(0, 0, 1);


// The specification's BRDF (glTF 2.0, appendix B.3), term by term in double precision, sharing
// no code with the renderer: mix(fresnel_mix(ior, Lambert, GGX), conductor_fresnel(base, GGX), metallic).
double gltf_brdf(const Material& m, const glm::vec3& wo, const glm::vec3& wi, int channel) {
    if (!(wo.z > 0.0f && wi.z > 0.0f)) return 0.0;
    const double alpha = std::max(1e-3, double(m.roughness) * m.roughness), a2 = alpha * alpha;
    const double hx = double(wo.x) + wi.x, hy = double(wo.y) + wi.y, hz = double(wo.z) + wi.z;
    const double hl = std::sqrt(hx * hx + hy * hy + hz * hz);
    const double n_h = hz / hl, v_h = (double(wo.x) * hx + double(wo.y) * hy + double(wo.z) * hz) / hl;
    const double t = n_h * n_h * (a2 - 1.0) + 1.0;
    const double d = a2 / (M_PI * t * t);
    const auto lambda = [&](double c) { return 0.5 * (std::sqrt(c * c + a2 * (1.0 - c * c)) / c - 1.0); };
    const double g2 = 1.0 / (1.0 + lambda(wo.z) + lambda(wi.z));
    const double specular_brdf = d * g2 / (4.0 * wo.z * wi.z);
    const double base = m.base_color[channel];
    const double r = (m.ior - 1.0) / (m.ior + 1.0);
    const double f0 = r * r, schlick = std::pow(1.0 - v_h, 5.0);
    const double fr = f0 + (1.0 - f0) * schlick;
    const double dielectric = (1.0 - fr) * base / M_PI + fr * specular_brdf;
    const double metal = (base + (1.0 - base) * schlick) * specular_brdf;
    return (1.0 - m.metallic) * dielectric + m.metallic * metal;
}

TEST(Principled, IsTheSpecificationsFormula) {
    std::mt19937 rng(21);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    for (const Material& m : {principled({0.8f, 0.5f, 0.2f}, 0.0f, 0.5f), principled({0.9f, 0.6f, 0.3f}, 0.4f, 0.25f),
                              principled({0.3f, 0.9f, 0.1f}, 0.8f, 1.0f, 1.33f), principled({1, 1, 1}, 0.0f, 0.7f, 4.0f)})
        for (int k = 0; k < 400; ++k) {
            const glm::vec3 wo = direction_at(1.5 * u(rng), 6.2 * u(rng)), wi = direction_at(1.5 * u(rng), 6.2 * u(rng));
            const glm::vec3 f = view(m, wo).f_cos(wi) / wi.z;
            for (int c = 0; c < 3; ++c) {
                const double expected = gltf_brdf(m, wo, wi, c);
                EXPECT_NEAR(f[c], expected, 2e-4 * expected + 1e-6) << m.metallic << " " << m.roughness << " " << c;
            }
        }
}

// One significance level for the chi-square tests below together (Sidak's correction).
constexpr int kChiSquareTests = 3 * 2 * 3;
const double kSignificance = 1.0 - std::pow(1.0 - 0.01, 1.0 / kChiSquareTests);

TEST(PrincipledSampling, LobeMixtureMatchesItsPdf) {
    uint32_t seed = 200;
    for (const Material& m : {principled({0.8f, 0.8f, 0.8f}, 0.0f, 0.3f), principled({0.9f, 0.5f, 0.2f}, 0.5f, 0.6f),
                              principled({0.05f, 0.05f, 0.05f}, 0.0f, 0.9f)})
        for (float theta : {0.2f, 1.0f, 1.45f}) {
            const MicrofacetBsdfAtView bsdf = view(m, direction_at(theta, 0.7));
            const double p = sampling_p_value(
                [&](float u0, float u1, float u2) {
                    const BsdfSample s = bsdf.sample(u0, u1, u2);
                    return Sampled{s.valid, s.direction};
                },
                [&](const glm::vec3& wi) { return double(bsdf.pdf(wi)); }, 200000, seed++);
            EXPECT_GT(p, kSignificance) << m.metallic << " " << m.roughness << " theta " << theta;
            // The pdf is the mixture's: no lobe is a delta, so every sample's pdf is finite.
            const PrincipledBrdf brdf(m.base_color, m.metallic, m.roughness, m.ior, direction_at(theta, 0.7));
            EXPECT_GT(brdf.specular_probability(), 0.0f);
            EXPECT_LT(brdf.specular_probability(), 1.0f);
        }
    // Sampling only one of the lobes would fail: a mixture pdf with the lobe choice left out
    // (here: the diffuse half alone) does not match the sampler.
    const MicrofacetBsdfAtView bsdf = view(principled({0.8f, 0.8f, 0.8f}, 0.0f, 0.3f), direction_at(1.0, 0.7));
    const double p = sampling_p_value(
        [&](float u0, float u1, float u2) {
            const BsdfSample s = bsdf.sample(u0, u1, u2);
            return Sampled{s.valid, s.direction};
        },
        [&](const glm::vec3& wi) { return wi.z > 0.0f ? double(wi.z) / M_PI : 0.0; }, 200000, 300);
    EXPECT_LT(p, 1e-6);
}

TEST(PrincipledSampling, WeightIsFCosOverTheMixturePdf) {
    std::mt19937 rng(22);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    int specular_samples = 0;
    for (const Material& m : {principled({0.8f, 0.5f, 0.2f}, 0.0f, 0.1f), principled({0.9f, 0.6f, 0.3f}, 0.5f, 0.6f),
                              principled({1, 1, 1}, 0.0f, 1.0f, 1.0f)})
        for (int k = 0; k < 500; ++k) {
            const float tolerance = m.roughness < 0.2f ? 0.02f : 2e-3f;  // as microfacet_bsdf_test: the half vector's rounding
            const MicrofacetBsdfAtView bsdf = view(m, direction_at(1.5 * u(rng), 6.2 * u(rng)));
            const BsdfSample s = bsdf.sample(u(rng), u(rng), u(rng));
            if (!s.valid) continue;
            EXPECT_TRUE(s.glossy && !s.specular);
            EXPECT_NEAR(s.pdf, bsdf.pdf(s.direction), tolerance * s.pdf);
            const glm::vec3 expected = bsdf.f_cos(s.direction) / s.pdf;
            for (int c = 0; c < 3; ++c) EXPECT_NEAR(s.weight[c], expected[c], tolerance * expected[c] + 1e-6f);
            if (s.pdf > 10.0f) ++specular_samples;
        }
    EXPECT_GT(specular_samples, 10);  // the sharp lobe was drawn too
}

TEST(Principled, IsReciprocal) {
    std::mt19937 rng(23);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    for (const Material& m : {principled({0.9f, 0.5f, 0.2f}, 0.3f, 0.4f), principled({0.5f, 0.5f, 0.5f}, 0.0f, 0.8f, 1.2f)})
        for (int k = 0; k < 500; ++k) {
            const glm::vec3 a = direction_at(1.5 * u(rng), 6.2 * u(rng)), b = direction_at(1.5 * u(rng), 6.2 * u(rng));
            const glm::vec3 fab = view(m, a).f_cos(b) / b.z, fba = view(m, b).f_cos(a) / a.z;
            for (int c = 0; c < 3; ++c) EXPECT_NEAR(fab[c], fba[c], 1e-4f * fab[c] + 1e-7f);
        }
}

// The diffuse half integrates to its share exactly and the specular half to its share less what
// its reflected visible normals send below the horizon: at most 1, at least the diffuse share.
TEST(Principled, PdfIntegratesToOneLessTheSpecularLobesMaskedShare) {
    for (const Material& m : {principled({0.8f, 0.8f, 0.8f}, 0.0f, 0.5f), principled({0.9f, 0.5f, 0.2f}, 0.5f, 1.0f)})
        for (float theta : {0.0f, 0.8f, 1.4f}) {
            const glm::vec3 wo = direction_at(theta, 0.3);
            const MicrofacetBsdfAtView bsdf = view(m, wo);
            const double integral = sphere_integral([&](const glm::vec3& wi) { return double(bsdf.pdf(wi)); }, 800);
            const float p = PrincipledBrdf(m.base_color, m.metallic, m.roughness, m.ior, wo).specular_probability();
            EXPECT_LT(integral, 1.0 + 3e-3) << theta;
            EXPECT_GT(integral, 1.0 - p - 3e-3) << theta;
            if (theta == 0.0f && m.roughness == 0.5f) {
                EXPECT_NEAR(integral, 1.0, 0.02);  // little is masked seen from above, moderately rough
            }
        }
}

TEST(PrincipledFurnace, NoMoreThanOneWithinFortyDegreesAndTheSpecificationsExcessAtGrazing) {
    for (const float metallic : {0.0f, 0.5f, 0.9f})
        for (const float roughness : {0.0f, 0.3f, 0.6f, 1.0f})
            for (const float theta : {0.0f, 0.35f, 0.7f}) {
                const MicrofacetBsdfAtView bsdf = view(principled(glm::vec3(1.0f), metallic, roughness), direction_at(theta, 0.2));
                const Albedo a = sampled_albedo(bsdf, 40000, 31);
                EXPECT_LE(a.mean, 1.0 + 4.0 * a.standard_error) << metallic << " " << roughness << " " << theta;
                EXPECT_GT(a.mean, 0.3) << metallic << " " << roughness << " " << theta;
                if (roughness >= 0.3f) {  // against the integral of f cos, independent of the sampler
                    const double quadrature = sphere_integral([&](const glm::vec3& wi) { return double(bsdf.f_cos(wi).x); }, 800);
                    EXPECT_NEAR(a.mean, quadrature, 4.0 * a.standard_error + 3e-3) << metallic << " " << roughness << " " << theta;
                }
            }
    // Past about 45 degrees a smooth white plastic reflects more than 1 (1.016 at 57 degrees), and
    // seen at 87 degrees, a white plastic's specular lobe reflects much of the light while the
    // diffuse lobe keeps (1 - F(wo.h)) near 1 for most wi: the specification's coupling is not
    // energy conserving there (principled.h). Both sides: above 1 at roughness 0.3, and not at 1.
    const double grazing = 1.5184;
    const Albedo smooth = sampled_albedo(view(principled(glm::vec3(1.0f), 0.0f, 0.3f), direction_at(grazing, 0.2)), 40000, 32);
    EXPECT_GT(smooth.mean, 1.2);
    EXPECT_LT(smooth.mean, 1.45);
    const Albedo rough = sampled_albedo(view(principled(glm::vec3(1.0f), 0.0f, 1.0f), direction_at(grazing, 0.2)), 40000, 33);
    EXPECT_LT(rough.mean, 1.03);
}

// Metallic 0, roughness 1: a Lambertian base under the specular lobe, the base seeing the light
// the lobe's Fresnel term leaves it, (1 - F(wo.h)) with F between 0.04 and a little more.
TEST(Principled, MetallicZeroRoughnessOneIsLambertUnderTheSpecularLobe) {
    const glm::vec3 base(0.6f, 0.4f, 0.2f);
    const Material m = principled(base, 0.0f, 1.0f);
    const RoughConductor specular(1.0f, ConductorFresnel{glm::vec3(0.04f)});
    std::mt19937 rng(24);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    for (int k = 0; k < 300; ++k) {
        // Within 0.5 rad of the normal wo.h >= cos((0.5 + pi / 2) / 2), so F <= 0.067.
        const glm::vec3 wo = direction_at(0.5 * u(rng), 6.2 * u(rng)), wi = direction_at(1.5 * u(rng), 6.2 * u(rng));
        const glm::vec3 diffuse = view(m, wo).f_cos(wi) / wi.z - specular.f(wo, wi);
        for (int c = 0; c < 3; ++c) {
            EXPECT_LE(diffuse[c], 0.96f * base[c] / float(M_PI) * (1.0f + 1e-5f));
            EXPECT_GE(diffuse[c], 0.933f * base[c] / float(M_PI));
        }
    }
    // Its albedo: the base's, less about 4%, plus the specular lobe's.
    const glm::vec3 wo = direction_at(0.5, 0.0);
    const double lobe = sphere_integral([&](const glm::vec3& wi) { return double(specular.f(wo, wi).x) * std::max(0.0f, wi.z); }, 600);
    const double whole = sphere_integral([&](const glm::vec3& wi) { return double(view(m, wo).f_cos(wi).x); }, 600);
    EXPECT_GT(whole - lobe, 0.93 * base.x);
    EXPECT_LT(whole - lobe, 0.96 * base.x);
}

TEST(PrincipledMaterial, MetallicOneIsTheConductorAndAtRoughnessZeroTheMirror) {
    const Material gold = principled_material({1.0f, 0.77f, 0.34f}, 1.0f, 0.3f, 1.5f, glm::vec3(0.0f));
    EXPECT_EQ(gold.type, MaterialType::rough_conductor);
    EXPECT_EQ(gold.f0, glm::vec3(1.0f, 0.77f, 0.34f));
    const Material chrome = principled_material(glm::vec3(1.0f), 1.0f, 0.0f, 1.5f, glm::vec3(0.0f));
    EXPECT_EQ(chrome.type, MaterialType::conductor);
    Material mirror;
    mirror.type = MaterialType::mirror;
    std::mt19937 rng(25);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    for (int k = 0; k < 500; ++k) {
        const glm::vec3 d = -direction_at(1.57 * u(rng), 6.28 * u(rng));
        const BsdfSample a = sample_bsdf(chrome, kUp, d, u(rng), u(rng), u(rng));
        const BsdfSample b = sample_bsdf(mirror, kUp, d, 0.5f, 0.5f, 0.5f);
        EXPECT_EQ(a.direction, b.direction);
        EXPECT_EQ(a.weight, glm::vec3(1.0f));  // white furnace: exactly 1
        EXPECT_EQ(a.weight, b.weight);
    }
    // Emitting, it stays principled (conductors do not emit), and reflects as the conductor does.
    const Material lamp = principled_material({0.9f, 0.6f, 0.3f}, 1.0f, 0.4f, 1.5f, glm::vec3(2.0f));
    EXPECT_EQ(lamp.type, MaterialType::principled);
    Material conductor = principled_material({0.9f, 0.6f, 0.3f}, 1.0f, 0.4f, 1.5f, glm::vec3(0.0f));
    for (int k = 0; k < 200; ++k) {
        const glm::vec3 wo = direction_at(1.5 * u(rng), 6.2 * u(rng)), wi = direction_at(1.5 * u(rng), 6.2 * u(rng));
        const glm::vec3 a = view(lamp, wo).f_cos(wi), b = view(conductor, wo).f_cos(wi);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(a[c], b[c], 1e-6f * b[c]);
    }
    // Any other metallic keeps both lobes; roughness 0 is the sharpest rough lobe.
    const Material plastic = principled_material(glm::vec3(0.5f), 0.0f, 0.0f, 1.5f, glm::vec3(0.0f));
    EXPECT_EQ(plastic.type, MaterialType::principled);
    EXPECT_TRUE(plastic.is_microfacet() && !plastic.is_specular());
}

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

TEST(PrincipledExtremes, NoNanOrInfinityAnywhere) {
    std::vector<Material> materials;
    for (float roughness : {0.0f, 1e-4f, 1.0f})
        for (float metallic : {0.0f, 0.5f, 1.0f})
            for (float ior : {1.0f, 1.5f, 4.0f})
                for (glm::vec3 base : {glm::vec3(0.0f), glm::vec3(1.0f)}) materials.push_back(principled(base, metallic, roughness, ior));
    std::mt19937 rng(26);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    for (const Material& m : materials)
        for (float theta : {0.0f, 0.5f, 1.5f, 1.5707f, 1.57079632f}) {
            const glm::vec3 wo = direction_at(theta, 1.0);
            const MicrofacetBsdfAtView bsdf = view(m, wo);
            for (int k = 0; k < 50; ++k) {
                const BsdfSample s = bsdf.sample(u(rng), u(rng), u(rng));
                if (s.valid) {
                    EXPECT_TRUE(finite(s.weight) && finite(s.direction)) << m.metallic << " " << m.roughness << " " << m.ior;
                    EXPECT_TRUE(s.pdf > 0.0f && std::isfinite(s.pdf));
                }
                const glm::vec3 wi = direction_at(3.14159 * u(rng), 6.28 * u(rng));
                EXPECT_TRUE(finite(bsdf.f_cos(wi)));
                EXPECT_TRUE(std::isfinite(bsdf.pdf(wi)) && bsdf.pdf(wi) >= 0.0f);
                for (const glm::vec3& special : {glm::vec3(-wo.x, -wo.y, wo.z), wo, kUp}) {
                    EXPECT_TRUE(finite(bsdf.f_cos(special)));
                    EXPECT_TRUE(std::isfinite(bsdf.pdf(special)));
                }
            }
        }
}

}  // namespace
}  // namespace wt
