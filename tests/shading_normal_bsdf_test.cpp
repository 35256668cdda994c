// Scattering about a shading normal (core/shading_normal_bsdf.h) against its definition: the
// folded diffuse kernel K that the light samples use integrates to rho whatever the shading
// normal is; BSDF sampling draws exactly K (chi-square for Lambert, weighted bins for
// Oren-Nayar), which is what makes light sampling and BSDF sampling estimate the same
// integral; no sampled direction leaves through the wrong side of the geometric surface, and
// none is NaN, for any normals; mirror and glass follow the shading normal where they can.
//
// False alarms: the hypothesis tests below (kFamily) share alpha 1e-3 by Bonferroni, with
// fixed seeds, as in statistical_test.cpp.

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "bsdf_helpers.h"
#include "core/materials/bsdf.h"
#include "core/sampling/sampling.h"
#include "core/materials/shading_normal_bsdf.h"
#include "statistics.h"

namespace wt {
namespace {

using test::diffuse;

constexpr int kFamily = 8;  // hypothesis tests in this file
constexpr double kPerTestAlpha = 1e-3 / kFamily;

// The unit vector at angle `tilt` from n, towards azimuth phi of n's frame.
glm::vec3 tilted(const glm::vec3& n, double tilt, double phi) {
    const Frame f(n);
    const glm::vec3 t = float(std::cos(phi)) * f.tangent + float(std::sin(phi)) * f.bitangent;
    return glm::normalize(float(std::cos(tilt)) * n + float(std::sin(tilt)) * t);
}

const glm::vec3 kGeometric = glm::normalize(glm::vec3(0.2f, -0.3f, 0.9f));

// The geometric hemisphere about n cut into cells of equal solid angle: z = dot(n, w) in
// (0, 1] in `bins_z` steps (solid angle is uniform in z), azimuth in `bins_phi`.
struct HemisphereGrid {
    glm::vec3 n;
    int bins_z, bins_phi;

    int cell(const glm::vec3& w) const {
        const Frame f(n);
        const double z = glm::dot(w, n);
        const double phi = std::atan2(double(glm::dot(w, f.bitangent)), double(glm::dot(w, f.tangent))) + M_PI;
        const int iz = std::min(bins_z - 1, int(z * bins_z)), ip = std::min(bins_phi - 1, int(phi / (2.0 * M_PI) * bins_phi));
        return iz * bins_phi + ip;
    }
    // The integral of g over each cell, by `sub` x `sub` midpoint quadrature per cell.
    template <typename G>
    std::vector<double> integrate(G&& g, int sub) const {
        const Frame f(n);
        std::vector<double> cells(std::size_t(bins_z * bins_phi), 0.0);
        const int nz = bins_z * sub, np = bins_phi * sub;
        const double dz = 1.0 / nz, dphi = 2.0 * M_PI / np;
        for (int i = 0; i < nz; ++i) {
            for (int j = 0; j < np; ++j) {
                const double z = (i + 0.5) * dz, phi = (j + 0.5) * dphi - M_PI, r = std::sqrt(1.0 - z * z);
                const glm::vec3 w = glm::normalize(float(r * std::cos(phi)) * f.tangent + float(r * std::sin(phi)) * f.bitangent +
                                                   float(z) * n);
                cells[std::size_t((i / sub) * bins_phi + j / sub)] += g(w) * dz * dphi;
            }
        }
        return cells;
    }
};

double sum(const std::vector<double>& v) {
    double s = 0.0;
    for (double x : v) s += x;
    return s;
}

// K(wi) of a material seen from wo, about shading normal ns, as DirectLightSampler evaluates it.
double folded_kernel(const Material& m, const glm::vec3& ng, const glm::vec3& ns, const glm::vec3& wo, const glm::vec3& wi) {
    const DiffuseBsdfAtView about_shading(m, ns, wo);
    return double(folded_diffuse(about_shading, ng, ns, wi, glm::dot(ng, wi)).x);
}

// The same about kGeometric, as a function of wi, for HemisphereGrid::integrate.
auto folded_kernel_of(const Material& m, const glm::vec3& ns, const glm::vec3& wo) {
    return [=](const glm::vec3& wi) { return folded_kernel(m, kGeometric, ns, wo, wi); };
}

TEST(FoldedDiffuse, LambertIntegratesToRhoForAnyShadingNormal) {
    const Material m = diffuse(MaterialType::lambertian, 0.7f);
    const glm::vec3 wo = tilted(kGeometric, 0.6, 2.0);
    const HemisphereGrid grid{kGeometric, 1, 1};
    // Raw shading normals from aligned to opposite, through tangent (90 degrees) and beyond,
    // turned to the viewer's side as the renderer turns them.
    for (double degrees : {0.0, 10.0, 45.0, 80.0, 89.9, 90.0, 100.0, 150.0, 180.0}) {
        const glm::vec3 ns = shading_normal_facing(tilted(kGeometric, degrees * M_PI / 180.0, 0.7), kGeometric);
        const double albedo = sum(grid.integrate(folded_kernel_of(m, ns, wo), 400));
        EXPECT_NEAR(albedo, 0.7, 2e-3) << degrees << " degrees";
    }
}

TEST(FoldedDiffuse, IsTheFlatBsdfTimesCosineWhenTheNormalsAgree) {
    for (const Material& m : {diffuse(MaterialType::lambertian, 0.6f), diffuse(MaterialType::oren_nayar, 0.6f, 0.9f)}) {
        const glm::vec3 wo = tilted(kGeometric, 1.1, 0.3);
        const DiffuseBsdfAtView flat(m, kGeometric, wo);
        std::mt19937 rng(3);
        std::uniform_real_distribution<double> u(0.0, 1.0);
        for (int i = 0; i < 1000; ++i) {
            const glm::vec3 wi = tilted(kGeometric, 1.5 * u(rng), 6.28 * u(rng));
            const float c = glm::dot(kGeometric, wi);
            const glm::vec3 expected = flat(wi, c) * c;
            const glm::vec3 folded = folded_diffuse(flat, kGeometric, kGeometric, wi, c);
            EXPECT_NEAR(folded.x, expected.x, 1e-6f * expected.x + 1e-9f);
        }
    }
}

// Oren-Nayar about a shading normal keeps its albedo below rho, also where the viewer is above
// the geometric surface but below the shading normal (where the flat BSDF would be zero: a
// black facet), and is not zero there.
TEST(FoldedDiffuse, OrenNayarNeverReflectsMoreThanRhoAndNeverGoesBlack) {
    const HemisphereGrid grid{kGeometric, 1, 1};
    for (float sigma : {0.3f, 0.9f, 2.0f}) {
        const Material m = diffuse(MaterialType::oren_nayar, 0.8f, sigma);
        for (double tilt_degrees : {30.0, 70.0, 90.0}) {
            const glm::vec3 ns = tilted(kGeometric, tilt_degrees * M_PI / 180.0, 0.0);
            for (double view_degrees : {10.0, 60.0, 85.0}) {
                // Azimuth pi: the viewer leans away from the shading normal, below it for large angles.
                const glm::vec3 wo = tilted(kGeometric, view_degrees * M_PI / 180.0, M_PI);
                const double albedo = sum(grid.integrate(folded_kernel_of(m, ns, wo), 300));
                const std::string where = "sigma " + std::to_string(sigma) + " tilt " + std::to_string(tilt_degrees) + " view " +
                                          std::to_string(view_degrees) + (glm::dot(ns, wo) < 0.0f ? " (viewer below ns)" : "");
                EXPECT_LE(albedo, 0.8 + 2e-3) << where;
                EXPECT_GT(albedo, 0.3) << where;
            }
        }
    }
}

// Sampling: directions of sample_bsdf_about_shading_normal, for Lambert, histogrammed over the
// geometric hemisphere, against the expected counts from K / rho, the light samples' kernel.
struct SampledHistogram {
    std::vector<double> counts, weight_sums, weight_square_sums;
    int invalid = 0;
};

SampledHistogram sample_histogram(const Material& m, const glm::vec3& ng, const glm::vec3& ns_raw, const glm::vec3& d, int n,
                                  uint32_t seed, const HemisphereGrid& grid) {
    SampledHistogram h;
    const std::size_t cells = std::size_t(grid.bins_z * grid.bins_phi);
    h.counts.assign(cells, 0.0), h.weight_sums.assign(cells, 0.0), h.weight_square_sums.assign(cells, 0.0);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    for (int i = 0; i < n; ++i) {
        const BsdfSample s = sample_bsdf_about_shading_normal(m, ng, ns_raw, d, u(rng), u(rng), u(rng), FresnelModel::schlick);
        if (!s.valid) {
            ++h.invalid;
            continue;
        }
        if (!(glm::dot(s.direction, grid.n) > 0.0f)) {
            ADD_FAILURE() << "sample " << i << " below the geometric surface";
            continue;
        }
        const std::size_t c = std::size_t(grid.cell(s.direction));
        h.counts[c] += 1.0;
        h.weight_sums[c] += s.weight.x;
        h.weight_square_sums[c] += double(s.weight.x) * s.weight.x;
    }
    return h;
}

TEST(FoldedDiffuseSampling, LambertDrawsTheKernelTheLightSamplesUse) {
    const Material m = diffuse(MaterialType::lambertian, 0.7f);
    const HemisphereGrid grid{kGeometric, 10, 20};
    const int n = 200000;
    uint32_t seed = 41;
    // The ray arrives from the geometric normal's side; shading normals tilted, tangent, and
    // (raw) 150 degrees off, which the sampler turns to 30 degrees on the ray's side.
    for (double degrees : {40.0, 80.0, 90.0, 150.0}) {
        const glm::vec3 ns_raw = tilted(kGeometric, degrees * M_PI / 180.0, 1.3);
        const glm::vec3 ns = shading_normal_facing(ns_raw, kGeometric);
        const glm::vec3 d = -tilted(kGeometric, 0.9, 4.0);
        const SampledHistogram h = sample_histogram(m, kGeometric, ns_raw, d, n, seed++, grid);
        EXPECT_LE(h.invalid, n / 10000);
        std::vector<double> expected = grid.integrate(folded_kernel_of(m, ns, -d), 8);
        for (double& e : expected) e *= double(n - h.invalid) / 0.7;  // K / rho is the density
        const test::ChiSquareResult r = test::chi_square_test(h.counts, expected);
        std::printf("lambert about ns %5.1f deg: chi2 %8.2f dof %d p %.4g\n", degrees, r.statistic, r.degrees_of_freedom,
                    r.p_value);
        EXPECT_GT(r.p_value, kPerTestAlpha) << degrees << " degrees";
        // Lambert's weight is rho, every time.
        for (std::size_t c = 0; c < h.counts.size(); ++c) EXPECT_NEAR(h.weight_sums[c], 0.7 * h.counts[c], 1e-3 * h.counts[c]);
    }
}

// The same histogram is not what cosine sampling about the geometric normal would give, nor what
// the shading-normal lobe without the fold would give: the test can tell them apart.
TEST(FoldedDiffuseSampling, TheHistogramTestRejectsTheUnfoldedAndTheFlatDensities) {
    const Material m = diffuse(MaterialType::lambertian, 0.7f);
    const HemisphereGrid grid{kGeometric, 10, 20};
    const int n = 200000;
    const glm::vec3 ns = tilted(kGeometric, 40.0 * M_PI / 180.0, 1.3);
    const glm::vec3 d = -tilted(kGeometric, 0.9, 4.0);
    const SampledHistogram h = sample_histogram(m, kGeometric, ns, d, n, 41, grid);
    std::vector<double> flat = grid.integrate([&](const glm::vec3& w) { return double(glm::dot(kGeometric, w)) / M_PI; }, 8);
    std::vector<double> unfolded = grid.integrate([&](const glm::vec3& w) { return std::max(0.0, double(glm::dot(ns, w))) / M_PI; }, 8);
    const double unfolded_total = sum(unfolded);  // below 1: the part below the surface is missing
    EXPECT_LT(unfolded_total, 0.99);
    for (double& e : flat) e *= n;
    for (double& e : unfolded) e *= n / unfolded_total;
    EXPECT_LT(test::chi_square_test(h.counts, flat).p_value, kPerTestAlpha);
    EXPECT_LT(test::chi_square_test(h.counts, unfolded).p_value, kPerTestAlpha);
}

// Oren-Nayar's weight varies, so each cell's mean weight times its frequency (an estimate of
// the integral of K over the cell) is z-tested against K's quadrature; the sum of the squared
// z's is chi-square with one degree per cell. The cells together give the albedo.
TEST(FoldedDiffuseSampling, OrenNayarWeightsIntegrateTheKernelCellByCell) {
    const HemisphereGrid grid{kGeometric, 8, 16};
    const int n = 400000;
    struct Case {
        float sigma;
        double tilt_degrees, view_degrees;
    };
    uint32_t seed = 51;
    for (const Case& c : {Case{0.9f, 60.0, 75.0}, Case{2.0f, 85.0, 40.0}, Case{0.5f, 30.0, 88.0}}) {
        const Material m = diffuse(MaterialType::oren_nayar, 0.8f, c.sigma);
        const glm::vec3 ns = tilted(kGeometric, c.tilt_degrees * M_PI / 180.0, 0.0);
        const glm::vec3 wo = tilted(kGeometric, c.view_degrees * M_PI / 180.0, M_PI);  // below ns for the first case
        const SampledHistogram h = sample_histogram(m, kGeometric, ns, -wo, n, seed++, grid);
        const std::vector<double> expected = grid.integrate(folded_kernel_of(m, ns, wo), 8);
        // Cells with few samples (behind a steep ns, where K is near zero) are pooled into one.
        double chi2 = 0.0, total = 0.0, pooled_mean = 0.0, pooled_expected = 0.0, pooled_variance = 0.0;
        int cells = 0;
        for (std::size_t k = 0; k < expected.size(); ++k) {
            const double mean = h.weight_sums[k] / n;
            const double variance = h.weight_square_sums[k] / n - mean * mean;
            total += mean;
            if (h.counts[k] < 100.0) {
                pooled_mean += mean, pooled_expected += expected[k], pooled_variance += variance;
                continue;
            }
            chi2 += (mean - expected[k]) * (mean - expected[k]) / (variance / n);
            ++cells;
        }
        if (pooled_variance > 0.0) {
            chi2 += (pooled_mean - pooled_expected) * (pooled_mean - pooled_expected) / (pooled_variance / n);
            ++cells;
        }
        const double p = test::chi_square_survival(chi2, double(cells));
        std::printf("oren-nayar sigma %.1f tilt %.0f view %.0f (ns.wo %.3f): chi2 %.1f dof %d p %.4g; albedo %.5f vs %.5f\n",
                    c.sigma, c.tilt_degrees, c.view_degrees, glm::dot(ns, wo), chi2, cells, p, total, sum(expected));
        EXPECT_GT(p, kPerTestAlpha) << "sigma " << c.sigma;
        EXPECT_LE(h.invalid, n / 10000);
    }
}

// Every material, arbitrary geometric and shading normals (random, tangent, opposite, nearly
// equal) and incoming directions down to grazing: a valid sample is finite and unit, reflects
// to the side the ray came from and refracts to the other, by the geometric normal.
TEST(ShadingNormalSampling, NoDirectionCrossesTheGeometricSurfaceTheWrongWay) {
    Material mirror, glass;
    mirror.type = MaterialType::mirror;
    glass.type = MaterialType::glass;
    glass.ior = 1.5f;
    const Material materials[] = {diffuse(MaterialType::lambertian, 0.8f), diffuse(MaterialType::oren_nayar, 0.8f, 0.9f), mirror, glass};
    std::mt19937 rng(61);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    auto random_unit = [&] { return tilted(glm::vec3(0, 0, 1), std::acos(1.0 - 2.0 * u(rng)), 2.0 * M_PI * u(rng)); };
    int invalid_diffuse = 0, diffuse_count = 0, transmitted = 0;
    for (int i = 0; i < 400000; ++i) {
        const Material& m = materials[i % 4];
        const glm::vec3 ng = random_unit();
        glm::vec3 ns;
        switch ((i / 4) % 4) {
            case 0: ns = random_unit(); break;
            case 1: ns = glm::normalize(glm::cross(ng, random_unit())); break;  // tangent
            case 2: ns = -ng; break;
            default: ns = tilted(ng, 1e-3 * u(rng), 6.28 * u(rng)); break;
        }
        // Incoming from either side, down to a cosine of 1e-6 with the geometric surface.
        const float cos_in = (i / 16) % 3 == 0 ? std::pow(10.0f, -6.0f * u(rng)) : u(rng);
        glm::vec3 d = -tilted(ng, std::acos(double(cos_in)), 6.28 * u(rng));
        if (u(rng) < 0.5f) d = glm::normalize(reflect(d, ng));  // from below
        if (glm::dot(d, ng) == 0.0f) continue;
        const glm::vec3 facing = glm::dot(d, ng) < 0.0f ? ng : -ng;
        const BsdfSample s = sample_bsdf_about_shading_normal(m, ng, ns, d, u(rng), u(rng), u(rng), FresnelModel::schlick);
        if (!m.is_specular()) {
            ++diffuse_count;
            if (!s.valid) {
                ++invalid_diffuse;
                continue;
            }
        }
        ASSERT_TRUE(s.valid) << "specular sample " << i;
        ASSERT_TRUE(std::isfinite(s.direction.x) && std::isfinite(s.direction.y) && std::isfinite(s.direction.z)) << i;
        ASSERT_TRUE(std::isfinite(s.weight.x) && s.weight.x >= 0.0f) << i;
        ASSERT_NEAR(glm::length(s.direction), 1.0f, 1e-5f) << i;
        const float side = glm::dot(s.direction, facing);
        if (s.transmitted) {
            ++transmitted;
            ASSERT_LT(side, 0.0f) << "refracted sample " << i << " came back out";
        } else {
            ASSERT_GT(side, 0.0f) << "reflected sample " << i << " went through the surface";
        }
    }
    EXPECT_LE(invalid_diffuse, diffuse_count / 10000);
    EXPECT_GT(transmitted, 10000);
}

TEST(ShadingNormalSampling, MirrorReflectsAboutTheShadingNormalWhenItCan) {
    Material mirror;
    mirror.type = MaterialType::mirror;
    mirror.reflectance = glm::vec3(0.9f);
    const glm::vec3 ng(0, 0, 1);
    const glm::vec3 ns = tilted(ng, 0.2, 0.0);
    // Near normal incidence the reflection about ns stays above the surface: it is used.
    const glm::vec3 d = glm::normalize(glm::vec3(0.1f, 0.2f, -1.0f));
    const BsdfSample s = sample_bsdf_about_shading_normal(mirror, ng, ns, d, 0, 0, 0, FresnelModel::schlick);
    const glm::vec3 expected = glm::normalize(reflect(d, ns));
    EXPECT_NEAR(glm::length(s.direction - expected), 0.0f, 1e-6f);
    EXPECT_EQ(s.weight, mirror.reflectance);
    // At grazing incidence from the side ns leans towards, the reflection about ns points into
    // the surface: it is mirrored back up through the tangent plane instead.
    const glm::vec3 grazing(std::cos(0.3f), 0.0f, -std::sin(0.3f));  // reflects to z = sin(-0.1) about ns
    const glm::vec3 about_ns = glm::normalize(reflect(grazing, ns));
    ASSERT_LT(about_ns.z, 0.0f);
    const BsdfSample g = sample_bsdf_about_shading_normal(mirror, ng, ns, grazing, 0, 0, 0, FresnelModel::schlick);
    EXPECT_NEAR(glm::length(g.direction - glm::vec3(about_ns.x, about_ns.y, -about_ns.z)), 0.0f, 1e-6f);
    // A ray arriving behind the shading normal (ns.d > 0) reflects about the geometric normal.
    const glm::vec3 behind = glm::normalize(glm::vec3(0.5f, 0.0f, -0.05f));
    ASSERT_GT(glm::dot(behind, ns), 0.0f);
    const BsdfSample b = sample_bsdf_about_shading_normal(mirror, ng, ns, behind, 0, 0, 0, FresnelModel::schlick);
    EXPECT_EQ(b.direction, sample_bsdf(mirror, ng, behind, 0, 0, 0).direction);
}

TEST(ShadingNormalSampling, GlassRefractsAboutTheShadingNormal) {
    Material glass;
    glass.type = MaterialType::glass;
    glass.ior = 1.5f;
    const glm::vec3 ng(0, 0, 1);
    const glm::vec3 ns = tilted(ng, 0.3, 0.0);
    const glm::vec3 d = glm::normalize(glm::vec3(0.2f, 0.1f, -1.0f));  // from outside
    const BsdfSample t = sample_bsdf_about_shading_normal(glass, ng, ns, d, 0, 0, 0.999f, FresnelModel::schlick);
    ASSERT_TRUE(t.transmitted);
    // Snell's law about ns: sin_t = sin_i / 1.5, in the plane of d and ns.
    const float sin_i = glm::length(glm::cross(d, ns)), sin_t = glm::length(glm::cross(t.direction, ns));
    EXPECT_NEAR(sin_t, sin_i / 1.5f, 1e-5f);
    EXPECT_NEAR(glm::dot(glm::cross(d, ns), t.direction), 0.0f, 1e-5f);
    EXPECT_LT(t.direction.z, 0.0f);
    // Leaving the glass (the ray inside, travelling along +z), beyond the critical angle about
    // ns: total internal reflection, back inside.
    const glm::vec3 inside = tilted(ns, 0.8, 0.0);
    const BsdfSample r = sample_bsdf_about_shading_normal(glass, ng, ns, inside, 0, 0, 0.999f, FresnelModel::schlick);
    EXPECT_FALSE(r.transmitted);
    EXPECT_LT(r.direction.z, 0.0f);
}

}  // namespace
}  // namespace wt
