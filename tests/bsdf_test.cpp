// The scattering models against their definitions: Oren-Nayar's limits and energy bound,
// consistency of each sampler's weight with f * cos / pdf, Fresnel and Snell at the angles
// where they are known in closed form.

#include <algorithm>
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "core/materials/bsdf.h"
#include "core/materials/fresnel.h"
#include "bsdf_helpers.h"

namespace wt {
namespace {

using test::diffuse;
using test::direction_at;
using test::directional_albedo;

const glm::vec3 kUp(0, 0, 1);

TEST(OrenNayar, SigmaZeroIsExactlyLambertian) {
    const Material lambert = diffuse(MaterialType::lambertian, 0.7f);
    const Material on = diffuse(MaterialType::oren_nayar, 0.7f, 0.0f);
    std::mt19937 rng(1);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    for (int i = 0; i < 1000; ++i) {
        const glm::vec3 wo = direction_at(1.55f * u(rng), 6.28f * u(rng));
        const glm::vec3 wi = direction_at(1.55f * u(rng), 6.28f * u(rng));
        EXPECT_EQ(eval_diffuse_bsdf(on, kUp, wo, wi), eval_diffuse_bsdf(lambert, kUp, wo, wi));
        const float u0 = u(rng), u1 = u(rng);
        const BsdfSample a = sample_bsdf(on, kUp, -wo, u0, u1, 0.5f);
        const BsdfSample b = sample_bsdf(lambert, kUp, -wo, u0, u1, 0.5f);
        EXPECT_EQ(a.direction, b.direction);
        EXPECT_EQ(a.weight, b.weight);
    }
}

TEST(OrenNayar, TermsMatchThePaper) {
    const OrenNayarTerms t = oren_nayar_terms(0.9f);
    EXPECT_NEAR(t.a, 1.0 - 0.5 * 0.81 / (0.81 + 0.33), 1e-6);
    EXPECT_NEAR(t.b, 0.45 * 0.81 / (0.81 + 0.09), 1e-6);
}

TEST(OrenNayar, BackscattersMoreThanLambertAtGrazingView) {
    // Rough surfaces look brighter towards the light (the paper's retro-reflection).
    const Material on = diffuse(MaterialType::oren_nayar, 1.0f, 0.9f);
    const glm::vec3 wo = direction_at(1.2f, 0.0f);
    const float retro = eval_diffuse_bsdf(on, kUp, wo, direction_at(1.2f, 0.0f)).x;
    const float forward = eval_diffuse_bsdf(on, kUp, wo, direction_at(1.2f, kPi)).x;
    EXPECT_GT(retro, forward);
}

TEST(OrenNayar, AlbedoNeverAboveRhoAtAnyRoughnessOrAngle) {
    for (float sigma : {0.0f, 0.3f, 0.9f, 2.0f, 10.0f}) {
        const Material m = diffuse(MaterialType::oren_nayar, 0.8f, sigma);
        for (float theta_o : {0.0f, 0.5f, 1.0f, 1.4f, 1.5607963f, 1.5707f}) {
            const double albedo = directional_albedo(m, direction_at(theta_o, 0.3f), 400);
            EXPECT_LE(albedo, 0.8 + 1e-3) << "sigma " << sigma << " theta_o " << theta_o;
            EXPECT_GT(albedo, 0.4) << "sigma " << sigma << " theta_o " << theta_o;
            EXPECT_TRUE(std::isfinite(albedo));
        }
    }
}

// The sampled weight against f cos / pdf computed independently of the renderer's BSDF code:
// Lambert's is the albedo itself (f = rho/pi, pdf = cos/pi); Oren-Nayar's is the published
// qualitative model in angles (Oren & Nayar 1994, eq. 30, in double: theta, phi from acos and
// atan2), with the energy scale 1/max(1, A + B/2) the README documents, where the renderer
// evaluates it without angles (bsdf.h).
double oren_nayar_weight_in_angles(double rho, double sigma, const glm::vec3& wo, const glm::vec3& wi) {
    const double theta_o = std::acos(double(wo.z)), theta_i = std::acos(double(wi.z));
    const double phi_o = std::atan2(double(wo.y), double(wo.x)), phi_i = std::atan2(double(wi.y), double(wi.x));
    const double s2 = sigma * sigma;
    const double a = 1.0 - 0.5 * s2 / (s2 + 0.33), b = 0.45 * s2 / (s2 + 0.09);
    const double scale = 1.0 / std::max(1.0, a + 0.5 * b);
    const double alpha = std::max(theta_i, theta_o), beta = std::min(theta_i, theta_o);
    return rho * scale * (a + b * std::max(0.0, std::cos(phi_i - phi_o)) * std::sin(alpha) * std::tan(beta));
}

TEST(DiffuseSampling, WeightEqualsBsdfTimesCosineOverPdf) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    const Material lambert = diffuse(MaterialType::lambertian, 0.6f), rough = diffuse(MaterialType::oren_nayar, 0.6f, 0.9f);
    double largest_oren_nayar_departure = 0.0;  // from Lambert's weight, so the comparison means something
    for (int i = 0; i < 2000; ++i) {
        const glm::vec3 wo = direction_at(1.5f * u(rng), 6.28f * u(rng));
        const float u1 = u(rng), u2 = u(rng), u3 = u(rng);
        const BsdfSample l = sample_bsdf(lambert, kUp, -wo, u1, u2, u3);
        ASSERT_TRUE(l.valid);
        EXPECT_FALSE(l.specular);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(l.weight[c], 0.6f, 1e-6f);
        const BsdfSample r = sample_bsdf(rough, kUp, -wo, u1, u2, u3);
        ASSERT_TRUE(r.valid);
        if (r.direction.z < 1e-3f) continue;  // grazing: the renderer's floor on max(cos) takes over
        const double expected = oren_nayar_weight_in_angles(0.6, 0.9, wo, r.direction);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(r.weight[c], expected, 1e-4 * expected + 1e-6) << "wo " << wo.z << " wi " << r.direction.z;
        largest_oren_nayar_departure = std::max(largest_oren_nayar_departure, std::fabs(expected - 0.6));
    }
    EXPECT_GT(largest_oren_nayar_departure, 0.1);
}

TEST(DiffuseSampling, SamplesTheSideTheRayCameFrom) {
    const Material m = diffuse(MaterialType::lambertian, 0.5f);
    const BsdfSample s = sample_bsdf(m, kUp, glm::normalize(glm::vec3(0.3f, 0, 1)), 0.3f, 0.7f, 0.5f);  // hits the back
    ASSERT_TRUE(s.valid);
    EXPECT_LT(s.direction.z, 0.0f);
}

TEST(Fresnel, SchlickAtNormalAndGrazingIncidence) {
    EXPECT_NEAR(schlick_reflectance(1.0f, 1.5f), 0.04f, 1e-7f);
    EXPECT_FLOAT_EQ(schlick_reflectance(0.0f, 1.5f), 1.0f);
    EXPECT_FLOAT_EQ(schlick_reflectance(1.0f, 1.0f), 0.0f);  // index-matched: no reflection
    float previous = 0.0f;
    for (float c = 1.0f; c >= 0.0f; c -= 0.01f) {  // monotone towards grazing
        const float r = schlick_reflectance(c, 1.5f);
        EXPECT_GE(r, previous);
        previous = r;
    }
}

TEST(Fresnel, SnellsLawAtThirtyDegrees) {
    const float theta = kPi / 6.0f;
    const glm::vec3 d(std::sin(theta), 0.0f, -std::cos(theta));
    const auto r = refract(d, kUp, 1.0f / 1.5f);
    ASSERT_TRUE(r.has_value());
    EXPECT_NEAR(r->direction.x, std::sin(theta) / 1.5f, 1e-6f);  // sin_t = sin_i * eta
    EXPECT_NEAR(glm::length(r->direction), 1.0f, 1e-6f);
    EXPECT_LT(r->direction.z, 0.0f);
    EXPECT_NEAR(r->cos_transmitted, -r->direction.z, 1e-6f);
}

TEST(Fresnel, TotalInternalReflectionAtTheCriticalAngle) {
    const float critical = std::asin(1.0f / 1.5f);
    auto ray_at = [](float theta) { return glm::vec3(std::sin(theta), 0.0f, -std::cos(theta)); };
    EXPECT_TRUE(refract(ray_at(critical - 1e-3f), kUp, 1.5f).has_value());
    EXPECT_FALSE(refract(ray_at(critical + 1e-3f), kUp, 1.5f).has_value());
    // Just below the critical angle the refracted ray skims the surface.
    EXPECT_LT(refract(ray_at(critical - 1e-3f), kUp, 1.5f)->cos_transmitted, 0.1f);
}

TEST(GlassSampling, ChoosesReflectionWithSchlickProbabilityAndWeightOne) {
    Material glass;
    glass.type = MaterialType::glass;
    glass.ior = 1.5f;
    const glm::vec3 d(0, 0, -1);  // normal incidence from outside: R = 0.04
    const BsdfSample reflected = sample_bsdf(glass, kUp, d, 0.5f, 0.5f, 0.039f);
    const BsdfSample refracted = sample_bsdf(glass, kUp, d, 0.5f, 0.5f, 0.041f);
    EXPECT_TRUE(reflected.specular && refracted.specular);
    EXPECT_NEAR(reflected.direction.z, 1.0f, 1e-6f);
    EXPECT_NEAR(refracted.direction.z, -1.0f, 1e-6f);
    EXPECT_EQ(reflected.weight, glm::vec3(1.0f));
    EXPECT_EQ(refracted.weight, glm::vec3(1.0f));
}

TEST(GlassSampling, InsideBeyondCriticalAngleAlwaysReflects) {
    Material glass;
    glass.type = MaterialType::glass;
    glass.ior = 1.5f;
    const float theta = std::asin(1.0f / 1.5f) + 0.01f;
    // From inside: the ray travels along +z towards the surface whose outward normal is +z.
    const glm::vec3 d(std::sin(theta), 0.0f, std::cos(theta));
    for (float u : {0.0f, 0.5f, 0.999f}) {
        const BsdfSample s = sample_bsdf(glass, kUp, d, 0.5f, 0.5f, u);
        EXPECT_LT(s.direction.z, 0.0f) << "u " << u;  // stays inside
        EXPECT_NEAR(s.direction.x, d.x, 1e-6f);
    }
}

TEST(GlassSampling, LeavingUsesTheOutsideAngleForSchlick) {
    Material glass;
    glass.type = MaterialType::glass;
    glass.ior = 1.5f;
    const float theta_inside = 0.5f;
    const glm::vec3 d(std::sin(theta_inside), 0.0f, std::cos(theta_inside));
    const float sin_out = 1.5f * std::sin(theta_inside);
    const float r = schlick_reflectance(std::sqrt(1.0f - sin_out * sin_out), 1.5f);
    // u < R reflects back inside; u >= R refracts out. The inside angle's Schlick value (~0.0400)
    // differs from the outside angle's (~0.0425) by far more than the 1e-4 probe.
    EXPECT_LT(sample_bsdf(glass, kUp, d, 0, 0, r - 1e-4f).direction.z, 0.0f);
    EXPECT_GT(sample_bsdf(glass, kUp, d, 0, 0, r + 1e-4f).direction.z, 0.0f);
}

TEST(MirrorSampling, ReflectsAboutTheNormalWithItsReflectance) {
    Material mirror;
    mirror.type = MaterialType::mirror;
    mirror.reflectance = glm::vec3(0.9f, 0.8f, 0.7f);
    const glm::vec3 d = glm::normalize(glm::vec3(1, 2, -3));
    const BsdfSample s = sample_bsdf(mirror, kUp, d, 0.1f, 0.2f, 0.3f);
    EXPECT_TRUE(s.specular);
    EXPECT_NEAR(s.direction.x, d.x, 1e-6f);
    EXPECT_NEAR(s.direction.y, d.y, 1e-6f);
    EXPECT_NEAR(s.direction.z, -d.z, 1e-6f);
    EXPECT_EQ(s.weight, mirror.reflectance);
}

}  // namespace
}  // namespace wt
