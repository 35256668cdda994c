#pragma once
// Exact form factors between the room's rectangles, in closed form: no sampling, no quadrature.
//
// Rectangle to rectangle: Stokes' theorem turns the double area integral of cos cos / (pi r^2)
// into a double contour integral (Sparrow 1963; Siegel & Howell, "Thermal Radiation Heat
// Transfer", the contour integration method):
//     A_1 F_12 = 1/(2 pi) * sum over edges e of C_1, f of C_2 of  integral integral ln r  de . df,
// each contour counter-clockwise about its own normal. For axis-aligned rectangles only
// parallel edges have de . df != 0, and for two parallel segments a distance d apart the
// double integral of ln sqrt((u - v)^2 + d^2) has a closed form (edge_pair_integral).
//
// Point to rectangle: Lambert's formula for the form factor from a differential area to a
// polygon, F = 1/(2 pi) * sum_k gamma_k n . (R_k x R_k+1) / |R_k x R_k+1|, gamma_k the angle
// the polygon's k-th edge subtends at the point (Baum, Rushmeier & Winget 1989, eq. 4).
//
// Both assume that the two sides see each other entirely, which holds in a box seen from inside.

#include <vector>

#include "oracle/vec3.h"

namespace oracle {

// A rectangle in a plane coordinate[axis] = lo[axis] = hi[axis], spanning [lo, hi] along the
// other two axes, with normal normal_sign * e_axis.
struct AxisRectangle {
    int axis = 2;
    Vec3 lo, hi;
    int normal_sign = 1;

    double area() const;
};

// F from `from` to `to`: the fraction of the radiosity leaving `from` that arrives at `to`.
// Zero for two rectangles in the same plane.
double rectangle_form_factor(const AxisRectangle& from, const AxisRectangle& to);

// The form factor from a differential area at `point` with unit normal `normal` to `to`.
double point_form_factor(const Vec3& point, const Vec3& normal, const AxisRectangle& to);

// point_form_factor to every patch of a grid in one plane: patch (i, j) is [nodes_a[i],
// nodes_a[i + 1]] x [nodes_b[j], nodes_b[j + 1]] (a, b: the plane's axes, the smaller first) in
// the plane coordinate[axis] = plane, with normal normal_sign * e_axis; its form factor goes to
// out[i * (nodes_b.size() - 1) + j]. Each grid edge's term in Lambert's sum is shared by the two
// patches it bounds (with opposite signs), so it is computed once: half the work.
void grid_point_form_factors(const Vec3& point, const Vec3& normal, int axis, double plane, int normal_sign,
                             const std::vector<double>& nodes_a, const std::vector<double>& nodes_b, std::vector<double>& out);

// The integral over u in [a1, a2] and v in [b1, b2] of ln sqrt((u - v)^2 + d^2).
double edge_pair_integral(double a1, double a2, double b1, double b2, double d);

}  // namespace oracle
