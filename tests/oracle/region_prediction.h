#pragma once
// What the oracle predicts a render of the room shows, pixel by pixel and region by region.
//
// Only pixels that see one smooth piece of radiance are predicted: the whole footprint of the
// pixel (its square on the film, cast into the room) on one wall, at least `edge_margin` from
// the wall's edges and wholly off the light (whose radiance jumps at its rim, and which shows Le
// exactly). There both the renderer's pixel mean and the oracle's quadrature are well defined.
//
// A region is a set of such pixels: those on one wall, or in one cell of the wall cut into
// cells_per_side x cells_per_side rectangles (the cell must hold the whole footprint).
//
// A pixel's prediction is its radiance averaged over its square, from two radiosity solutions of
// patch sizes h_coarse > h_fine, Richardson-extrapolated to h = 0 with the order 2 the final
// gather converges at, with a bound on what that leaves (see RoomOracle).

#include <array>
#include <memory>
#include <vector>

#include "oracle/pinhole_view.h"
#include "oracle/room.h"

namespace oracle {

struct OracleSettings {
    // Patch edge lengths of the two solutions; each must divide the room's sizes and the light's
    // edges into whole numbers of patches.
    double coarse_patch = 1.0 / 16.0;
    double fine_patch = 1.0 / 24.0;
    // A third, rougher solution, only for bounding the pixel quadrature of the indirect light
    // (how much the radiance bends across a pixel, which a 1 % error in the radiance hardly
    // changes), where the patch count multiplies the cost of every quadrature point.
    double quadrature_patch = 1.0 / 8.0;
    int cells_per_side = 2;
    // Near a concave edge the radiance bends sharply (its gradient grows like the log of the
    // distance): a pixel's quadrature and the patches' discretisation are at their worst there.
    double edge_margin = 0.08;
};

struct PixelRegion {
    int wall = 0;
    int cell_a = -1, cell_b = -1;  // the cell along wall_plane_axes(); -1, -1: the whole wall
    std::vector<int> pixels;       // row-major indices, ascending
};

// Every wall's region (those with a pixel), then every cell's.
std::vector<PixelRegion> pixel_regions(const Room& room, const PinholeCamera& camera, const OracleSettings& settings);

struct PixelPrediction {
    Rgb radiance{};     // the mean radiance over the pixel's square
    Rgb error_bound{};  // |radiance - the exact mean| is at most this
};

struct ViewPrediction {
    std::vector<PixelRegion> regions;
    std::vector<PixelPrediction> pixels;  // row-major, every pixel of the image; zero outside the regions
};

class RadiositySolution;

// The room solved at two resolutions, for the renderer's `max_bounces` (1: direct light only,
// which needs no patches but the light's and is exact up to the pixel quadrature); then any
// number of views predicted from the solutions.
//
// A pixel's error bound adds three parts. Direct light (from the light, in closed form): the
// 4 x 4 Gauss-Legendre rule over the pixel, bounded by its distance from the 3 x 3 rule.
// Indirect light: the 2 x 2 rule on the coarse solution, bounded by the distance between the
// 2 x 2 and 3 x 3 rules on the quadrature solution; and the discretisation: its error behaves as
// C h^p, so the exact value is fine + (fine - coarse) / (s^p - 1), s = h_coarse / h_fine (the
// step from the pixel centres). For any order p in [kLowestOrder,
// kHighestOrder] (the `long` test measures it from three resolutions) that lies between the
// values at the two ends; the prediction is their midpoint and the bound their half-distance.
class RoomOracle {
public:
    RoomOracle(const Room& room, int max_bounces, const OracleSettings& settings);
    ~RoomOracle();
    RoomOracle(const RoomOracle&) = delete;
    RoomOracle& operator=(const RoomOracle&) = delete;

    ViewPrediction predict(const PinholeCamera& camera) const;
    PixelPrediction predict_pixel(const PinholeCamera& camera, int pixel) const;

    const RadiositySolution& coarse() const { return *coarse_; }
    const RadiositySolution& fine() const { return *fine_; }
    std::array<int, 3> coarse_cells() const;

private:
    Room room_;
    OracleSettings settings_;
    std::unique_ptr<RadiositySolution> coarse_, fine_, rough_;
};

// The final gather's order of convergence, measured over this room's regions at h = 1/8 .. 1/32:
// 1.45 to 1.9, rising with refinement (the edges' log singularity), below the textbook 2.
constexpr double kLowestOrder = 1.25, kHighestOrder = 2.5;

// The exact value is fine + t (fine - coarse), t = 1/(s^p - 1) for an order p in [kLowestOrder,
// kHighestOrder]: the middle of t's range, and half its width.
struct RichardsonStep {
    double middle, half_width;
};
RichardsonStep richardson_step(double refinement);

}  // namespace oracle
