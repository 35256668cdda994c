#pragma once
// The directional albedo of the GGX reflection lobe with a Fresnel term of one,
//     E(mu_o, roughness) = integral of D G2 / (4 mu_o mu_i) mu_i over the hemisphere of wi,
// the energy single scattering keeps of light arriving at cosine mu_o (ggx.h, rough_conductor.h),
// and its cosine-weighted average E_avg(roughness) = 2 integral_0^1 E(mu) mu dmu. Kulla & Conty
// 2017 ("Revisiting Physically Based Shading at Imageworks") give back the 1 - E that single
// scattering loses from these two (multiple_scattering.h).
//
// Tabulated once per process on a grid of mu_o and perceptual roughness (the roughness the scene
// files give, alpha = roughness^2 as ggx_alpha), as Imageworks and Cycles precompute theirs, and
// read bilinearly. The grid is uniform in mu_o^(1/4), not in mu_o: for smooth lobes E climbs from
// 0 to 1 within mu_o of about alpha of the horizon, which a uniform grid cannot follow. The
// table is computed, not shipped: a deterministic quadrature of the renderer's own lobe,
// rough_conductor.h's visible-normal sampler, in a fixed order, so it holds exactly what that
// lobe loses, whatever the changes to it, and is the same on every machine.
// E_avg is the exact integral of the interpolant, not of the true E: with it the compensation
// lobe's albedo is exactly 1 - E(mu_o) of the table (multiple_scattering.h), and a white rough
// metal reflects 1 within the table's error of E.

#include <array>

namespace wt {

class GgxAlbedoTable {
public:
    static constexpr int kCosines = 64;     // mu_o = (i / (kCosines - 1))^4, i = 0 ... kCosines - 1
    static constexpr int kRoughnesses = 32; // roughness = j / (kRoughnesses - 1)
    static constexpr int kAzimuths = 32;    // visible normals per grid point: kAzimuths x kHeights
    static constexpr int kHeights = 64;

    // mu_o of grid point i.
    static float cosine_at(int i);

    GgxAlbedoTable();

    // E at (mu_o, roughness), both clamped to [0, 1]; bilinear between the grid points.
    float albedo(float cos_o, float roughness) const;
    // E_avg at a roughness, linear between the grid's roughnesses (as albedo() is, so it is the
    // integral of what albedo() returns).
    float average(float roughness) const;

    // A grid point's value, for the tests.
    float at(int cos_index, int roughness_index) const { return albedo_[roughness_index][cos_index]; }

private:
    std::array<std::array<float, kCosines>, kRoughnesses> albedo_{};
    std::array<float, kRoughnesses> average_{};
};

// The process's table, computed on first use (build_scene asks for it before rendering when a
// scene needs it, so no render waits for it mid-way).
const GgxAlbedoTable& ggx_albedo_table();

}  // namespace wt
