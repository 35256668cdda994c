#include "core/materials/ggx_albedo.h"

#include <algorithm>
#include <cmath>

#include "core/materials/ggx.h"
#include "core/materials/rough_conductor.h"

namespace wt {

namespace {

// Exactly at the horizon G1(wo) is 0 and the sampler's pdf 0 / 0: every sample is lost. E is
// continuous there, so the grid's first points read it a hair above the horizon.
constexpr float kMinCosine = 1e-6f;

// E(mu_o) of one alpha: the mean of the sampler's weight G2 / G1(wo) (f cos / pdf with F = 1)
// over a grid of visible normals, a lost (masked) sample counting 0. The lobe is mirror-symmetric
// about the plane of wo and the normal (wo.y = 0), so the azimuths u0 span half the circle, at
// midpoints. The heights u1 are graded towards 1, u1 = 1 - (1 - t)^2 with t at midpoints and the
// Jacobian 2 (1 - t): the sampler maps the last few percent of u1 to the steep microfacets,
// where the weight falls from 1 to 0, which a uniform grid resolves with only a point or two
// (bench/README.md has the errors of both grids).
double directional_albedo(float alpha, float cos_o) {
    const RoughConductor lobe(alpha, ConductorFresnel{glm::vec3(1.0f)});
    const glm::vec3 wo(std::sqrt(std::max(0.0f, 1.0f - cos_o * cos_o)), 0.0f, cos_o);
    constexpr int azimuths = GgxAlbedoTable::kAzimuths, heights = GgxAlbedoTable::kHeights;
    double sum = 0.0;
    for (int b = 0; b < heights; ++b) {
        const double rest = 1.0 - (double(b) + 0.5) / heights;
        const float u1 = float(1.0 - rest * rest);
        double row = 0.0;
        for (int a = 0; a < azimuths; ++a) {
            const MicrofacetSample s = lobe.sample(wo, (float(a) + 0.5f) / float(2 * azimuths), u1);
            if (s.valid) row += double(s.weight.x);
        }
        sum += row * 2.0 * rest;
    }
    return sum / (double(azimuths) * double(heights));
}

// 2 integral_0^1 e(mu) mu dmu for e linear in x = mu^(1/4) between the grid points: with
// mu = x^4, 8 integral e(x) x^7 dx, a polynomial of degree 8 on each segment, which 5-point
// Gauss-Legendre integrates exactly.
template <std::size_t N>
double cosine_weighted_average(const std::array<float, N>& e) {
    static constexpr double nodes[5] = {-0.9061798459386640, -0.5384693101056831, 0.0, 0.5384693101056831, 0.9061798459386640};
    static constexpr double weights[5] = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889, 0.4786286704993665,
                                          0.2369268850561891};
    double sum = 0.0;
    for (std::size_t i = 0; i + 1 < N; ++i) {
        const double a = double(i) / double(N - 1), b = double(i + 1) / double(N - 1);
        for (int k = 0; k < 5; ++k) {
            const double t = 0.5 * (nodes[k] + 1.0), x = a + t * (b - a);
            const double value = double(e[i]) + t * (double(e[i + 1]) - double(e[i]));
            sum += weights[k] * 0.5 * (b - a) * value * std::pow(x, 7);
        }
    }
    return 8.0 * sum;
}

// The grid cell holding x in [0, 1] of a grid of n points, and where in it x lies.
struct Cell {
    int index;
    float t;
};
Cell cell_of(float x, int n) {
    const float clamped = x > 0.0f ? std::min(x, 1.0f) : 0.0f;  // NaN to 0, as std::clamp would not
    const float scaled = clamped * float(n - 1);
    const int index = std::min(int(scaled), n - 2);
    return {index, scaled - float(index)};
}

}  // namespace

float GgxAlbedoTable::cosine_at(int i) {
    const float x = float(i) / float(kCosines - 1);
    return (x * x) * (x * x);
}

GgxAlbedoTable::GgxAlbedoTable() {
    for (int j = 0; j < kRoughnesses; ++j) {
        const float alpha = ggx_alpha(float(j) / float(kRoughnesses - 1));
        for (int i = 0; i < kCosines; ++i)
            albedo_[j][i] = float(std::min(1.0, directional_albedo(alpha, std::max(kMinCosine, cosine_at(i)))));
        average_[j] = float(cosine_weighted_average(albedo_[j]));
    }
}

float GgxAlbedoTable::albedo(float cos_o, float roughness) const {
    // The grid's x = mu^(1/4); two square roots are exact and cheaper than a power.
    const float x = cos_o > 0.0f ? std::sqrt(std::sqrt(cos_o)) : 0.0f;
    const Cell c = cell_of(x, kCosines), r = cell_of(roughness, kRoughnesses);
    const auto row = [&](int j) { return albedo_[j][c.index] + c.t * (albedo_[j][c.index + 1] - albedo_[j][c.index]); };
    const float low = row(r.index), high = row(r.index + 1);
    return low + r.t * (high - low);
}

float GgxAlbedoTable::average(float roughness) const {
    const Cell r = cell_of(roughness, kRoughnesses);
    return average_[r.index] + r.t * (average_[r.index + 1] - average_[r.index]);
}

const GgxAlbedoTable& ggx_albedo_table() {
    static const GgxAlbedoTable table;  // thread-safe initialisation (C++11 magic statics)
    return table;
}

}  // namespace wt
