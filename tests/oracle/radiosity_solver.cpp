#include "oracle/radiosity_solver.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace oracle {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Where a patch's lower corner is, in cells along each axis (its plane axis: 0, or the cell
// count for the wall at the far side).
using Lattice = std::array<int, 3>;

// A light edge at `coordinate` must be a whole number of cells of size `cell`.
void check_on_boundary(double coordinate, double cell, const char* what) {
    const double cells = coordinate / cell;
    if (std::fabs(cells - std::round(cells)) > 1e-9)
        throw std::invalid_argument(std::string("oracle: the light's ") + what + " (" + std::to_string(coordinate) +
                                    ") is not on a patch boundary (cell " + std::to_string(cell) + ")");
}

// The form factors between the patches of two walls depend only on how far apart the two
// patches are (in cells, per axis): the walls are planes and the grids uniform. A table per
// pair of walls holds each distinct value once, computed the first time it is needed, so the
// matrix costs the closed form of O(n^3) pairs, not O(n^4).
class OffsetTable {
public:
    OffsetTable(const std::array<int, 3>& lowest, const std::array<int, 3>& highest) : lowest_(lowest) {
        for (int a = 0; a < 3; ++a) extent_[a] = highest[a] - lowest[a] + 1;
        values_.assign(std::size_t(extent_[0]) * std::size_t(extent_[1]) * std::size_t(extent_[2]), NAN);
    }
    double& at(const Lattice& from, const Lattice& to) {
        std::size_t index = 0;
        for (int a = 0; a < 3; ++a) index = index * std::size_t(extent_[a]) + std::size_t(to[a] - from[a] - lowest_[a]);
        return values_[index];
    }

private:
    std::array<int, 3> lowest_, extent_;
    std::vector<double> values_;
};

Vec3 inward_normal(int wall) {
    Vec3 n;
    n[wall_axis(wall)] = wall_normal_sign(wall);
    return n;
}

}  // namespace

RadiositySolution::RadiositySolution(const Room& room, std::array<int, 3> cells, int max_bounces) : room_(room) {
    if (max_bounces < 1) throw std::invalid_argument("oracle: max_bounces must be at least 1");
    for (int a = 0; a < 3; ++a)
        if (cells[a] < 1) throw std::invalid_argument("oracle: at least one patch per axis");
    const double cell_x = room.size.x / cells[0], cell_y = room.size.y / cells[1];
    check_on_boundary(room.light_lo.x, cell_x, "lower x edge");
    check_on_boundary(room.light_hi.x, cell_x, "upper x edge");
    check_on_boundary(room.light_lo.y, cell_y, "lower y edge");
    check_on_boundary(room.light_hi.y, cell_y, "upper y edge");
    light_.axis = 2;
    light_.normal_sign = -1;
    light_.lo = {room.light_lo.x, room.light_lo.y, room.size.z};
    light_.hi = {room.light_hi.x, room.light_hi.y, room.size.z};
    make_patches(cells);
    if (max_bounces == 1) {
        // Light reflected once only: no radiosity but the light's own, no form factor needed.
        for (const Patch& p : patches_) radiosity_.push_back(p.emitted);
        reflected_once_only_ = true;
        return;
    }
    solve(form_factor_matrix(cells), max_bounces);
}

void RadiositySolution::make_patches(std::array<int, 3> cells) {
    for (int wall = 0; wall < kWalls; ++wall) {
        const int u = wall_axis(wall);
        const std::array<int, 2> axes = wall_plane_axes(wall);
        const double plane = wall_side(wall) == 0 ? 0.0 : room_.size[u];
        WallGrid& grid = grids_[wall];
        grid.first = patches_.size();
        for (int k = 0; k < 2; ++k) {
            grid.cells[k] = cells[axes[k]];
            // From the cell index, not by accumulation, so that neighbours share edges exactly.
            for (int i = 0; i <= grid.cells[k]; ++i) grid.nodes[k].push_back(room_.size[axes[k]] * i / grid.cells[k]);
        }
        for (int i = 0; i < grid.cells[0]; ++i) {
            for (int j = 0; j < grid.cells[1]; ++j) {
                Patch p;
                p.wall = wall;
                p.rectangle.axis = u;
                p.rectangle.normal_sign = wall_normal_sign(wall);
                p.rectangle.lo[u] = p.rectangle.hi[u] = plane;
                p.rectangle.lo[axes[0]] = grid.nodes[0][i];
                p.rectangle.hi[axes[0]] = grid.nodes[0][i + 1];
                p.rectangle.lo[axes[1]] = grid.nodes[1][j];
                p.rectangle.hi[axes[1]] = grid.nodes[1][j + 1];
                p.albedo = room_.albedo[wall];
                const Vec3 centre = 0.5 * (p.rectangle.lo + p.rectangle.hi);
                if (wall == kCeiling && room_.in_light(centre)) {
                    p.light = true;
                    p.albedo = {0.0, 0.0, 0.0};
                    for (int c = 0; c < 3; ++c) p.emitted[c] = kPi * room_.light_radiance[c];
                }
                patches_.push_back(p);
            }
        }
    }
}

std::vector<float> RadiositySolution::form_factor_matrix(std::array<int, 3> cells) {
    const std::size_t n = patches_.size();
    std::vector<Lattice> where(n);
    for (std::size_t i = 0; i < n; ++i)
        for (int a = 0; a < 3; ++a) where[i][a] = int(std::lround(patches_[i].rectangle.lo[a] / room_.size[a] * cells[a]));
    auto first = [&](int wall) { return grids_[wall].first; };
    auto end = [&](int wall) { return wall + 1 < kWalls ? grids_[wall + 1].first : n; };

    // Transposed, F_ij in column j: solve() says why. Each pair of walls once, the other way
    // round by reciprocity, A_i F_ij = A_j F_ji (the patches of a wall all have one area).
    // Stored in float: its rounding (a relative 6e-8 per entry, which the solution inherits) is
    // far below any tolerance here, and it halves what each iteration streams from memory. The
    // row sums check the closed forms, before that rounding.
    std::vector<float> f(n * n, 0.0f);
    std::vector<double> row_sum(n, 0.0);
    for (int wi = 0; wi < kWalls; ++wi) {
        for (int wj = wi + 1; wj < kWalls; ++wj) {
            std::array<int, 3> lowest{}, highest{};
            for (int a = 0; a < 3; ++a) {
                lowest[a] = where[first(wj)][a] - where[end(wi) - 1][a];
                highest[a] = where[end(wj) - 1][a] - where[first(wi)][a];
            }
            OffsetTable table(lowest, highest);
            const double area_ratio = patches_[first(wi)].rectangle.area() / patches_[first(wj)].rectangle.area();
            for (std::size_t j = first(wj); j < end(wj); ++j) {
                for (std::size_t i = first(wi); i < end(wi); ++i) {
                    double& value = table.at(where[i], where[j]);
                    if (std::isnan(value)) value = rectangle_form_factor(patches_[i].rectangle, patches_[j].rectangle);
                    f[j * n + i] = float(value);
                    f[i * n + j] = float(value * area_ratio);
                    row_sum[i] += value;
                    row_sum[j] += value * area_ratio;
                }
            }
        }
    }
    for (double row : row_sum) worst_row_sum_error_ = std::max(worst_row_sum_error_, std::fabs(row - 1.0));
    return f;
}

void RadiositySolution::solve(const std::vector<float>& f, int max_bounces) {
    const std::size_t n = patches_.size();
    double brightest_albedo = 0.0, largest = 0.0;
    for (const Patch& p : patches_) {
        for (double a : p.albedo) brightest_albedo = std::max(brightest_albedo, a);
        for (double e : p.emitted) largest = std::max(largest, e);
    }
    // B^(0) = E; B^(m+1) = E + rho F B^(m), accumulated as increments rho F (rho F)^m E. The rows
    // of F sum to 1, so each increment is at most brightest_albedo times the last, and the
    // increments not added sum to at most last * brightest / (1 - brightest): stop when that is
    // below 1e-8 of the light's radiosity (a hundred-thousandth of the tests' tolerances).
    // One array per channel and F stored by columns, so that the product is a sum of columns
    // scaled by one number each: a loop the compiler vectorises (a row's dot product would be a
    // reduction, which it may not reorder).
    std::array<std::vector<double>, 3> total, increment, gathered;
    for (int c = 0; c < 3; ++c) {
        total[c].resize(n);
        increment[c].resize(n);
        for (std::size_t i = 0; i < n; ++i) total[c][i] = increment[c][i] = patches_[i].emitted[c];
    }
    iterations_ = 0;
    for (int m = 1; m < max_bounces; ++m) {
        for (int c = 0; c < 3; ++c) gathered[c].assign(n, 0.0);
        double* g0 = gathered[0].data();
        double* g1 = gathered[1].data();
        double* g2 = gathered[2].data();
        // In blocks of rows, so that the sums being added to stay in the L1 cache while the
        // matrix streams past once.
        constexpr std::size_t kBlock = 512;
        for (std::size_t i0 = 0; i0 < n; i0 += kBlock) {
            const std::size_t i1 = std::min(n, i0 + kBlock);
            for (std::size_t j = 0; j < n; ++j) {
                const double b0 = increment[0][j], b1 = increment[1][j], b2 = increment[2][j];
                if (b0 == 0.0 && b1 == 0.0 && b2 == 0.0) continue;  // the first bounce gathers from the light alone
                const float* column = &f[j * n];
                for (std::size_t i = i0; i < i1; ++i) {
                    g0[i] += column[i] * b0;
                    g1[i] += column[i] * b1;
                    g2[i] += column[i] * b2;
                }
            }
        }
        double step = 0.0;
        for (int c = 0; c < 3; ++c) {
            for (std::size_t i = 0; i < n; ++i) {
                increment[c][i] = patches_[i].albedo[c] * gathered[c][i];
                total[c][i] += increment[c][i];
                step = std::max(step, increment[c][i]);
            }
        }
        iterations_ = m;
        if (step * brightest_albedo / (1.0 - brightest_albedo) < 1e-8 * largest) break;
    }
    radiosity_.resize(n);
    for (std::size_t i = 0; i < n; ++i) radiosity_[i] = {total[0][i], total[1][i], total[2][i]};
}

Rgb RadiositySolution::direct_radiance(int wall, const Vec3& point) const {
    if (wall == kCeiling && room_.in_light(point)) return room_.light_radiance;  // it reflects nothing
    // rho / pi * (pi Le) * F(point -> light).
    const double f = wall == kCeiling ? 0.0 : point_form_factor(point, inward_normal(wall), light_);
    Rgb l{};
    for (int c = 0; c < 3; ++c) l[c] = room_.albedo[wall][c] * room_.light_radiance[c] * f;
    return l;
}

Rgb RadiositySolution::indirect_radiance(int wall, const Vec3& point) const {
    if (reflected_once_only_ || (wall == kCeiling && room_.in_light(point))) return {0.0, 0.0, 0.0};
    Rgb gathered{0.0, 0.0, 0.0};
    std::vector<double> f;
    for (int other = 0; other < kWalls; ++other) {
        if (other == wall) continue;
        const WallGrid& grid = grids_[other];
        const int axis = wall_axis(other);
        grid_point_form_factors(point, inward_normal(wall), axis, wall_side(other) == 0 ? 0.0 : room_.size[axis],
                                wall_normal_sign(other), grid.nodes[0], grid.nodes[1], f);
        for (std::size_t k = 0; k < f.size(); ++k) {
            const std::size_t patch = grid.first + k;
            if (patches_[patch].light) continue;  // direct_radiance's part
            for (int c = 0; c < 3; ++c) gathered[c] += f[k] * radiosity_[patch][c];
        }
    }
    Rgb l{};
    for (int c = 0; c < 3; ++c) l[c] = room_.albedo[wall][c] / kPi * gathered[c];
    return l;
}

}  // namespace oracle
