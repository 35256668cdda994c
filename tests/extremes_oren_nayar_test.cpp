// Oren-Nayar at exactly grazing view and very large roughness.

#include "extremes_helpers.h"

namespace wt::extremes {
namespace {

// ---- Oren-Nayar at grazing view and large roughness ---------------------------------------------

Material oren_nayar(float sigma, float albedo = 0.8f) {
    Material m;
    m.type = MaterialType::oren_nayar;
    m.albedo = glm::vec3(albedo);
    m.sigma = sigma;
    return m;
}


TEST(OrenNayarExtremes, GrazingViewAndLargeSigmaStayFiniteAndBelowRho) {
    const double half_pi = M_PI / 2.0;
    // theta_o within 1e-4 of 90 degrees, a float step below it, and exactly 90 degrees (the
    // view direction in the tangent plane: cos_o = 0, and as a denormal).
    std::vector<std::pair<std::string, glm::vec3>> views;
    for (double off : {1e-4, 5e-5, 1e-6}) views.push_back({"90 deg - " + std::to_string(off) + " rad", direction_at(half_pi - off, 0.3)});
    views.push_back({"exactly 90 deg", glm::vec3(1, 0, 0)});
    views.push_back({"exactly 90 deg, other azimuth", glm::vec3(-0.6f, 0.8f, 0)});
    views.push_back({"90 deg, cos_o = denorm_min", glm::vec3(1, 0, std::numeric_limits<float>::denorm_min())});
    views.push_back({"90 deg, cos_o = -0", glm::vec3(0.8f, 0.6f, -0.0f)});
    const float rho = 0.8f;
    std::mt19937 rng(41);
    std::uniform_real_distribution<float> u01(0.0f, 1.0f);
    for (float sigma : {0.3f, 1.0f, 10.0f, 100.0f}) {
        const Material m = oren_nayar(sigma, rho);
        for (const auto& [name, wo] : views) {
            SCOPED_TRACE("sigma " + std::to_string(sigma) + ", view " + name + " " + hex(wo));
            const double albedo = directional_albedo(m, wo, 300);
            EXPECT_TRUE(std::isfinite(albedo));
            EXPECT_LE(albedo, rho + 1e-3);
            EXPECT_GE(albedo, 0.0);
            // eval at grazing wi too, including exactly in the tangent plane.
            for (const glm::vec3 wi : {wo, glm::vec3(-wo.x, -wo.y, wo.z), glm::vec3(1, 0, 0), direction_at(half_pi - 1e-4, 3.0),
                                       glm::vec3(0, 0, 1), glm::vec3(0, 1, 1e-30f)}) {
                const glm::vec3 f = eval_diffuse_bsdf(m, kUp, wo, wi);
                ASSERT_TRUE(std::isfinite(f.x) && f.x >= 0.0f) << "wi " << hex(wi) << " f " << f.x;
            }
            // Sampled weights: finite, non-negative, on the side the ray came from. The ray
            // arrives along -wo; with wo exactly in the tangent plane it counts as a back hit.
            // Their mean is the directional albedo (the quadrature above), up to its noise.
            double weight_sum = 0.0, weight_squares = 0.0;
            const int n = 20000;
            for (int k = 0; k < n; ++k) {
                const BsdfSample s = sample_bsdf(m, kUp, -wo, u01(rng), u01(rng), u01(rng));
                if (!s.valid) continue;
                ASSERT_TRUE(std::isfinite(s.weight.x) && s.weight.x >= 0.0f) << "weight " << s.weight.x << " direction " << hex(s.direction);
                ASSERT_TRUE(std::isfinite(s.direction.x) && std::isfinite(s.direction.y) && std::isfinite(s.direction.z));
                weight_sum += s.weight.x;
                weight_squares += double(s.weight.x) * double(s.weight.x);
            }
            if (wo.z > 0.0f) {
                const double mean = weight_sum / n, sd = std::sqrt(std::max(0.0, weight_squares / n - mean * mean));
                EXPECT_NEAR(mean, albedo, 5.0 * sd / std::sqrt(double(n)) + 2e-3);
            }
        }
    }
}


}  // namespace
}  // namespace wt::extremes
