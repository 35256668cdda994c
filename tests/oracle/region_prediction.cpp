#include "oracle/region_prediction.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>

#include "oracle/radiosity_solver.h"

namespace oracle {
namespace {

// Patches per axis for a patch edge length: a whole number, or an error.
std::array<int, 3> cells_for(const Room& room, double patch) {
    std::array<int, 3> cells{};
    for (int a = 0; a < 3; ++a) {
        const double n = room.size[a] / patch;
        if (std::fabs(n - std::round(n)) > 1e-9 || n < 1.0)
            throw std::invalid_argument("oracle: patch size " + std::to_string(patch) + " does not divide the room's size " +
                                        std::to_string(room.size[a]));
        cells[a] = int(std::lround(n));
    }
    return cells;
}

// A pixel's footprint on a wall, as the bounding box of its corners in the wall's plane
// coordinates. The footprint is the corners' convex hull (a pinhole maps the pixel's square
// onto a plane in front of it projectively), so it lies inside any rectangle that box is in.
struct Footprint {
    bool one_wall = true;
    int wall = 0;
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
};

Footprint footprint(const Room& room, const PinholeCamera& camera, int x, int y) {
    Footprint f;
    for (int corner = 0; corner < 4; ++corner) {
        const WallPoint w = seen_at(room, camera, x + (corner & 1), y + (corner >> 1));
        if (corner == 0) f.wall = w.wall;
        if (w.wall != f.wall) f.one_wall = false;
        const std::array<int, 2> axes = wall_plane_axes(w.wall);
        for (int k = 0; k < 2; ++k) {
            f.lo[k] = std::min(f.lo[k], w.point[axes[k]]);
            f.hi[k] = std::max(f.hi[k], w.point[axes[k]]);
        }
    }
    return f;
}

// Whether [lo, hi] lies strictly inside (from, to), by more than a rounding error.
bool strictly_inside(double lo, double hi, double from, double to) {
    const double margin = 1e-9;
    return lo > from + margin && hi < to - margin;
}

// Gauss-Legendre rules with n = 1 .. 4 points on [-1/2, 1/2] (offsets from a pixel's centre,
// weights summing to 1); the product rule of n x n points is exact for polynomials of degree
// 2n - 1 in each film coordinate.
struct GaussRule {
    double offset[4], weight[4];
};
constexpr GaussRule kGauss[5] = {
    {{}, {}},
    {{0.0}, {1.0}},
    {{-0.28867513459481288, 0.28867513459481288}, {0.5, 0.5}},
    {{-0.38729833462074169, 0.0, 0.38729833462074169}, {5.0 / 18.0, 8.0 / 18.0, 5.0 / 18.0}},
    {{-0.43056815579702629, -0.16999052179242813, 0.16999052179242813, 0.43056815579702629},
     {0.17392742256872693, 0.32607257743127307, 0.32607257743127307, 0.17392742256872693}},
};

// radiance(what film position sees) averaged over pixel `p`'s square by the n x n rule.
template <typename Radiance>
Rgb pixel_mean(int p, const Room& room, const PinholeCamera& camera, int n, Radiance&& radiance) {
    const GaussRule& rule = kGauss[n];
    const double cx = p % camera.width + 0.5, cy = p / camera.width + 0.5;
    Rgb sum{0.0, 0.0, 0.0};
    for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) {
            const WallPoint w = seen_at(room, camera, cx + rule.offset[i], cy + rule.offset[j]);
            const Rgb l = radiance(w.wall, w.point);
            for (int c = 0; c < 3; ++c) sum[c] += rule.weight[i] * rule.weight[j] * l[c];
        }
    }
    return sum;
}

double richardson_factor(double refinement, double order) { return 1.0 / (std::pow(refinement, order) - 1.0); }

}  // namespace

std::vector<PixelRegion> pixel_regions(const Room& room, const PinholeCamera& camera, const OracleSettings& settings) {
    std::map<std::pair<int, int>, PixelRegion> cells[kWalls];
    PixelRegion walls[kWalls];
    const int per_side = settings.cells_per_side;
    for (int y = 0; y < camera.height; ++y) {
        for (int x = 0; x < camera.width; ++x) {
            const Footprint f = footprint(room, camera, x, y);
            if (!f.one_wall) continue;
            const std::array<int, 2> axes = wall_plane_axes(f.wall);
            bool clean = true;
            for (int k = 0; k < 2; ++k)
                clean = clean && strictly_inside(f.lo[k], f.hi[k], settings.edge_margin, room.size[axes[k]] - settings.edge_margin);
            if (f.wall == kCeiling) {
                const bool off_light = f.hi[0] < room.light_lo.x - 1e-9 || f.lo[0] > room.light_hi.x + 1e-9 ||
                                       f.hi[1] < room.light_lo.y - 1e-9 || f.lo[1] > room.light_hi.y + 1e-9;
                clean = clean && off_light;
            }
            if (!clean) continue;
            const int pixel = y * camera.width + x;
            walls[f.wall].wall = f.wall;
            walls[f.wall].pixels.push_back(pixel);
            int cell[2];
            bool in_cell = true;
            for (int k = 0; k < 2; ++k) {
                const double extent = room.size[axes[k]];
                cell[k] = std::clamp(int(std::floor(f.lo[k] / extent * per_side)), 0, per_side - 1);
                in_cell = in_cell && strictly_inside(f.lo[k], f.hi[k], extent * cell[k] / per_side, extent * (cell[k] + 1) / per_side);
            }
            if (!in_cell) continue;
            PixelRegion& r = cells[f.wall][{cell[0], cell[1]}];
            r.wall = f.wall;
            r.cell_a = cell[0];
            r.cell_b = cell[1];
            r.pixels.push_back(pixel);
        }
    }
    std::vector<PixelRegion> out;
    for (const PixelRegion& w : walls)
        if (!w.pixels.empty()) out.push_back(w);
    for (const auto& wall : cells)
        for (const auto& [key, r] : wall) out.push_back(r);
    return out;
}

RichardsonStep richardson_step(double refinement) {
    const double most = richardson_factor(refinement, kLowestOrder), least = richardson_factor(refinement, kHighestOrder);
    return {0.5 * (most + least), 0.5 * (most - least)};
}

RoomOracle::RoomOracle(const Room& room, int max_bounces, const OracleSettings& settings)
    : room_(room), settings_(settings) {
    if (!(settings.coarse_patch > settings.fine_patch))
        throw std::invalid_argument("oracle: the coarse patches must be larger than the fine ones");
    coarse_ = std::make_unique<RadiositySolution>(room, cells_for(room, settings.coarse_patch), max_bounces);
    fine_ = std::make_unique<RadiositySolution>(room, cells_for(room, settings.fine_patch), max_bounces);
    rough_ = std::make_unique<RadiositySolution>(room, cells_for(room, settings.quadrature_patch), max_bounces);
}

RoomOracle::~RoomOracle() = default;

std::array<int, 3> RoomOracle::coarse_cells() const { return cells_for(room_, settings_.coarse_patch); }

PixelPrediction RoomOracle::predict_pixel(const PinholeCamera& camera, int pixel) const {
    const RichardsonStep richardson = richardson_step(settings_.coarse_patch / settings_.fine_patch);
    auto direct = [&](int wall, const Vec3& p) { return coarse_->direct_radiance(wall, p); };
    auto indirect_coarse = [&](int wall, const Vec3& p) { return coarse_->indirect_radiance(wall, p); };
    auto indirect_fine = [&](int wall, const Vec3& p) { return fine_->indirect_radiance(wall, p); };
    auto indirect_rough = [&](int wall, const Vec3& p) { return rough_->indirect_radiance(wall, p); };
    // Direct light: exact but for the quadrature, and cheap (one rectangle per point).
    const Rgb direct4 = pixel_mean(pixel, room_, camera, 4, direct), direct3 = pixel_mean(pixel, room_, camera, 3, direct);
    // Indirect light, smooth over a pixel: the step to the fine solution from the pixel centres
    // (a difference of a few tenths of a percent of the value, whose own quadrature error is
    // smaller than that again by the quadrature's relative error).
    const Rgb coarse2 = pixel_mean(pixel, room_, camera, 2, indirect_coarse);
    const Rgb coarse1 = pixel_mean(pixel, room_, camera, 1, indirect_coarse);
    const Rgb fine1 = pixel_mean(pixel, room_, camera, 1, indirect_fine);
    const Rgb rough3 = pixel_mean(pixel, room_, camera, 3, indirect_rough);
    const Rgb rough2 = pixel_mean(pixel, room_, camera, 2, indirect_rough);
    PixelPrediction p;
    for (int c = 0; c < 3; ++c) {
        const double step = fine1[c] - coarse1[c];
        p.radiance[c] = direct4[c] + coarse2[c] + (1.0 + richardson.middle) * step;
        p.error_bound[c] =
            std::fabs(direct4[c] - direct3[c]) + std::fabs(rough3[c] - rough2[c]) + richardson.half_width * std::fabs(step);
    }
    return p;
}

ViewPrediction RoomOracle::predict(const PinholeCamera& camera) const {
    ViewPrediction view;
    view.regions = pixel_regions(room_, camera, settings_);
    view.pixels.assign(std::size_t(camera.width) * std::size_t(camera.height), PixelPrediction{});
    for (const PixelRegion& r : view.regions)
        if (r.cell_a < 0)  // the walls' regions hold every cell's pixels
            for (int p : r.pixels) view.pixels[std::size_t(p)] = predict_pixel(camera, p);
    return view;
}

}  // namespace oracle
