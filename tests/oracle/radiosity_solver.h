#pragma once
// The room's radiosity, solved from scratch: every wall cut into a grid of patches, the exact
// patch-to-patch form factors (form_factors.h), the linear system B = E + rho F B solved by
// Jacobi iteration, and the radiance at any point by a final gather of the patches' radiosity
// through the exact point-to-patch form factors.
//
// Why Jacobi: its m-th iterate is the radiosity of light reflected at most m times, so the
// solution can be cut where a renderer's paths are cut. A path tracer that shades vertices
// 0 .. K-1 with next-event estimation (max_bounces = K) sees at its first hit Le + rho/pi *
// (gather of the radiosity of light reflected at most K-1 times): iterate K-1 times.
//
// Discretisation error: a patch carries one constant radiosity, so B is approximated to O(h)
// pointwise, but the final gather integrates that error against a smooth kernel, which makes
// the radiance at interior points converge much faster (for the Galerkin method with constant
// elements, whose patch averages are superconvergent, O(h^2); Atkinson, "The Numerical Solution
// of Integral Equations of the Second Kind", 1997, ch. 3-4). The `long` oracle test measures
// the order from three resolutions instead of trusting it. The direct part needs no patches:
// the light's radiosity is its emission, exactly, and its form factor is in closed form.

#include <array>
#include <cstddef>
#include <vector>

#include "oracle/form_factors.h"
#include "oracle/room.h"

namespace oracle {

struct Patch {
    int wall = 0;
    AxisRectangle rectangle;
    Rgb emitted{};  // radiosity emitted, pi * Le (light patches only)
    Rgb albedo{};
    bool light = false;
};

class RadiositySolution {
public:
    // `cells`: patches along x, y and z (every wall crossing that axis is cut the same way).
    // Throws std::invalid_argument when the light's edges do not fall on patch boundaries, so
    // that every patch is either all light or none. `max_bounces`: as the renderer's setting.
    RadiositySolution(const Room& room, std::array<int, 3> cells, int max_bounces);

    // Radiance leaving `point` (on `wall`, inside the room) in any direction: what is emitted
    // there plus what was reflected once, from the light (exact, in closed form) ...
    Rgb direct_radiance(int wall, const Vec3& point) const;
    // ... plus what was reflected two or more times (the final gather of the walls' radiosity).
    Rgb indirect_radiance(int wall, const Vec3& point) const;

    const std::vector<Patch>& patches() const { return patches_; }
    const std::vector<Rgb>& radiosity() const { return radiosity_; }
    // Largest |sum_j F_ij - 1| over the patches, in double (before the matrix is stored in float):
    // in a closed room every row sums to 1.
    double worst_row_sum_error() const { return worst_row_sum_error_; }
    int jacobi_iterations() const { return iterations_; }

private:
    // A wall's patches: cells[0] x cells[1] along wall_plane_axes(), patch (i, j) at index
    // first + i * cells[1] + j; its grid lines at nodes[0] and nodes[1].
    struct WallGrid {
        std::size_t first = 0;
        std::array<int, 2> cells{};
        std::array<std::vector<double>, 2> nodes;
    };

    void make_patches(std::array<int, 3> cells);
    std::vector<float> form_factor_matrix(std::array<int, 3> cells);
    void solve(const std::vector<float>& form_factors, int max_bounces);

    Room room_;
    bool reflected_once_only_ = false;  // max_bounces 1: nothing but the light has radiosity
    AxisRectangle light_;
    std::array<WallGrid, kWalls> grids_;
    std::vector<Patch> patches_;
    std::vector<Rgb> radiosity_;
    double worst_row_sum_error_ = 0.0;
    int iterations_ = 0;
};

}  // namespace oracle
