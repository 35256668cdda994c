// The radiosity oracle's own parts against what is known without it: published form factors,
// the closed room's energy, brute-force quadrature, and (label `long`) the order its final
// gather converges at, which its error bound assumes.

#include <cmath>
#include <cstdio>
#include <vector>

#include <gtest/gtest.h>

#include "oracle/form_factors.h"
#include "oracle/radiosity_solver.h"
#include "oracle/region_prediction.h"
#include "oracle_scenes.h"

#ifndef WT_LONG_TESTS
#define WT_LONG_TESTS 0
#endif

namespace oracle {
namespace {

constexpr double kPi = 3.14159265358979323846;

AxisRectangle rectangle(int axis, double plane, Vec3 lo, Vec3 hi, int normal_sign) {
    AxisRectangle r;
    r.axis = axis;
    r.lo = lo;
    r.hi = hi;
    r.lo[axis] = r.hi[axis] = plane;
    r.normal_sign = normal_sign;
    return r;
}

// Siegel & Howell's catalogue (configurations C-11 and C-14): two unit squares facing each
// other at distance 1, 0.19982; two at right angles sharing an edge, 0.20004.
TEST(OracleFormFactors, PublishedValues) {
    const AxisRectangle floor = rectangle(2, 0.0, {0, 0, 0}, {1, 1, 0}, +1);
    const AxisRectangle ceiling = rectangle(2, 1.0, {0, 0, 0}, {1, 1, 0}, -1);
    const AxisRectangle wall = rectangle(0, 0.0, {0, 0, 0}, {0, 1, 1}, +1);
    EXPECT_NEAR(rectangle_form_factor(floor, ceiling), 0.19982, 1e-5);
    EXPECT_NEAR(rectangle_form_factor(floor, wall), 0.20004, 1e-5);
    EXPECT_NEAR(rectangle_form_factor(wall, floor), 0.20004, 1e-5);
    EXPECT_EQ(rectangle_form_factor(floor, rectangle(2, 0.0, {1, 0, 0}, {2, 1, 0}, +1)), 0.0);  // coplanar
    // From the centre of the floor to the unit square 1 above it: four times the form factor from
    // a point to a parallel a x b rectangle at distance 1 with a corner above it, a = b = 1/2,
    // (1 / 2 pi) * 2 * (a / sqrt(1 + a^2)) * atan(b / sqrt(1 + a^2)).
    const double a = 0.5, s = std::sqrt(1 + a * a);
    EXPECT_NEAR(point_form_factor({0.5, 0.5, 0}, {0, 0, 1}, ceiling), 4.0 / kPi * (a / s) * std::atan(a / s), 1e-12);
}

// The double area integral of cos cos / (pi r^2) by the midpoint rule on grids fine enough for
// a pair of rectangles that are far apart compared to their size.
double brute_force_form_factor(const AxisRectangle& from, const AxisRectangle& to, int n) {
    auto points = [n](const AxisRectangle& r) {
        std::vector<Vec3> p;
        const int a = (r.axis + 1) % 3, b = (r.axis + 2) % 3;
        for (int i = 0; i < n; ++i) {
            for (int j = 0; j < n; ++j) {
                Vec3 q = r.lo;
                q[a] = r.lo[a] + (r.hi[a] - r.lo[a]) * (i + 0.5) / n;
                q[b] = r.lo[b] + (r.hi[b] - r.lo[b]) * (j + 0.5) / n;
                p.push_back(q);
            }
        }
        return p;
    };
    Vec3 nf, nt;
    nf[from.axis] = from.normal_sign;
    nt[to.axis] = to.normal_sign;
    double sum = 0.0;
    const std::vector<Vec3> pf = points(from), pt = points(to);
    for (const Vec3& x : pf) {
        for (const Vec3& y : pt) {
            const Vec3 d = y - x;
            const double r2 = dot(d, d);
            sum += dot(nf, d) * -dot(nt, d) / (kPi * r2 * r2);
        }
    }
    return sum * to.area() / double(pf.size() * pt.size());
}

TEST(OracleFormFactors, ClosedFormsAgreeWithBruteForceQuadrature) {
    const AxisRectangle floor_patch = rectangle(2, 0.0, {0.2, 0.1, 0}, {0.3, 0.25, 0}, +1);
    const AxisRectangle far_wall_patch = rectangle(1, 1.0, {0.5, 1, 0.3}, {0.7, 1, 0.45}, -1);
    const AxisRectangle ceiling_patch = rectangle(2, 0.75, {0.6, 0.5, 0}, {0.72, 0.6, 0}, -1);
    for (const AxisRectangle* to : {&far_wall_patch, &ceiling_patch}) {
        const double exact = rectangle_form_factor(floor_patch, *to);
        EXPECT_NEAR(exact, brute_force_form_factor(floor_patch, *to, 24), 2e-4 * exact);
        // Reciprocity: A_i F_ij = A_j F_ji.
        EXPECT_NEAR(floor_patch.area() * exact, to->area() * rectangle_form_factor(*to, floor_patch), 1e-15);
        // Lambert's point formula, averaged over the source, is the rectangle's form factor.
        double averaged = 0.0;
        const int n = 16;
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j)
                averaged += point_form_factor({0.2 + 0.1 * (i + 0.5) / n, 0.1 + 0.15 * (j + 0.5) / n, 0.0}, {0, 0, 1}, *to);
        EXPECT_NEAR(averaged / (n * n), exact, 1e-4 * exact);
    }
}

TEST(OracleFormFactors, GridOfPatchesEqualsEachPatchAlone) {
    const std::vector<double> xs = {0.0, 0.25, 0.5, 0.75, 1.0}, ys = {0.0, 0.4, 0.8, 1.25};
    std::vector<double> grid;
    const Vec3 point{0.3, 0.2, 0.0}, normal{0.0, 0.0, 1.0};
    grid_point_form_factors(point, normal, 2, 0.75, -1, xs, ys, grid);
    ASSERT_EQ(grid.size(), 4u * 3u);
    double total = 0.0;
    for (int i = 0; i < 4; ++i) {
        for (int j = 0; j < 3; ++j) {
            const double alone = point_form_factor(point, normal, rectangle(2, 0.75, {xs[i], ys[j], 0}, {xs[i + 1], ys[j + 1], 0}, -1));
            EXPECT_NEAR(grid[i * 3 + j], alone, 1e-15);
            EXPECT_GT(alone, 0.0);
            total += alone;
        }
    }
    EXPECT_NEAR(total, point_form_factor(point, normal, rectangle(2, 0.75, {0, 0, 0}, {1, 1.25, 0}, -1)), 1e-14);
}

// In a closed room every patch's form factors sum to 1, and at equilibrium the power the light
// emits is the power the walls absorb: sum A E = sum A (1 - rho) H, H = sum_j F_ij B_j.
TEST(OracleRadiosity, ClosedRoomConservesEnergy) {
    const Room room = wt::test::oracle_room();
    const RadiositySolution s(room, {16, 20, 12}, 1000);
    EXPECT_LT(s.worst_row_sum_error(), 1e-12);
    double emitted[3] = {0, 0, 0}, absorbed[3] = {0, 0, 0};
    const std::vector<Patch>& patches = s.patches();
    for (std::size_t i = 0; i < patches.size(); ++i) {
        const double area = patches[i].rectangle.area();
        for (int c = 0; c < 3; ++c) {
            emitted[c] += area * patches[i].emitted[c];
            if (patches[i].light) continue;  // albedo 0: it absorbs all it receives, counted below
            // B = E + rho H, so (1 - rho) H = (1 - rho) (B - E) / rho.
            absorbed[c] += area * (1.0 - patches[i].albedo[c]) * s.radiosity()[i][c] / patches[i].albedo[c];
        }
    }
    // What the light absorbs: the light's own H, gathered from every other patch's B.
    for (std::size_t i = 0; i < patches.size(); ++i) {
        if (!patches[i].light) continue;
        for (std::size_t j = 0; j < patches.size(); ++j) {
            if (patches[j].wall == patches[i].wall) continue;
            const double f = rectangle_form_factor(patches[i].rectangle, patches[j].rectangle);
            for (int c = 0; c < 3; ++c) absorbed[c] += patches[i].rectangle.area() * f * s.radiosity()[j][c];
        }
    }
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(absorbed[c], emitted[c], 1e-6 * emitted[c]) << "channel " << c;
}

// The m-th Jacobi iterate is light reflected at most m times: with max_bounces 2, a wall's
// radiosity is rho * (its form factor to the light) * pi Le (to the float the matrix is kept in).
TEST(OracleRadiosity, BounceLimitedSolutionIsTheNeumannSeriesCut) {
    const Room room = wt::test::oracle_room();
    const RadiositySolution s(room, {8, 10, 6}, 2);
    AxisRectangle light = rectangle(2, room.size.z, room.light_lo, room.light_hi, -1);
    for (std::size_t i : {std::size_t(0), std::size_t(57), std::size_t(200)}) {
        const Patch& p = s.patches()[i];
        ASSERT_FALSE(p.light);
        const double f = rectangle_form_factor(p.rectangle, light);
        for (int c = 0; c < 3; ++c) {
            const double expected = p.albedo[c] * f * kPi * room.light_radiance[c];
            EXPECT_NEAR(s.radiosity()[i][c], expected, 1e-6 * expected);
        }
    }
}

TEST(OracleRadiosity, RefusesAGridThatCutsTheLight) {
    EXPECT_THROW(RadiositySolution(wt::test::oracle_room(), {10, 10, 6}, 2), std::invalid_argument);
}

// The error bound (region_prediction.h) assumes the final gather converges at an order p in
// [kLowestOrder, kHighestOrder]. From three resolutions h1 > h2 > h3 the ratio of successive
// differences (h1^p - h2^p) / (h2^p - h3^p) gives p; measured for every region of both views.
double difference_ratio(double h1, double h2, double h3, double p) {
    return (std::pow(h1, p) - std::pow(h2, p)) / (std::pow(h2, p) - std::pow(h3, p));
}

TEST(OracleRadiosity, FinalGatherConvergesAtTheOrderTheBoundAssumes) {
    if (!WT_LONG_TESTS) GTEST_SKIP() << "label long: oracle_long_test";
    const Room room = wt::test::oracle_room();
    const double h[3] = {1.0 / 16, 1.0 / 24, 1.0 / 32};
    std::vector<RadiositySolution> solutions;
    for (double patch : h) solutions.emplace_back(room, std::array<int, 3>{int(1 / patch), int(1.25 / patch), int(0.75 / patch)}, 64);
    const double lowest = difference_ratio(h[0], h[1], h[2], kLowestOrder), highest = difference_ratio(h[0], h[1], h[2], kHighestOrder);
    for (const PinholeCamera& camera : {wt::test::oracle_room_view(), wt::test::oracle_ceiling_view()}) {
        for (const PixelRegion& r : pixel_regions(room, camera, OracleSettings{})) {
            double mean[3][3] = {};
            for (int level = 0; level < 3; ++level) {
                for (int p : r.pixels) {
                    const WallPoint w = seen_at(room, camera, p % camera.width + 0.5, p / camera.width + 0.5);
                    const Rgb l = solutions[std::size_t(level)].indirect_radiance(w.wall, w.point);
                    for (int c = 0; c < 3; ++c) mean[level][c] += l[c] / double(r.pixels.size());
                }
            }
            for (int c = 0; c < 3; ++c) {
                const double ratio = (mean[1][c] - mean[0][c]) / (mean[2][c] - mean[1][c]);
                std::printf("wall %d cell (%d, %d) channel %d: %.7f %.7f %.7f, ratio %.3f (order %.2f .. %.2f: %.3f .. %.3f)\n",
                            r.wall, r.cell_a, r.cell_b, c, mean[0][c], mean[1][c], mean[2][c], ratio, kLowestOrder,
                            kHighestOrder, lowest, highest);
                EXPECT_GT(ratio, lowest) << "wall " << r.wall << " cell " << r.cell_a << ", " << r.cell_b;
                EXPECT_LT(ratio, highest) << "wall " << r.wall << " cell " << r.cell_a << ", " << r.cell_b;
            }
        }
    }
}

}  // namespace
}  // namespace oracle
