#include "oracle/form_factors.h"

#include <array>
#include <cmath>

namespace oracle {
namespace {

constexpr double kPi = 3.14159265358979323846;

// An antiderivative of the antiderivative of (1/2) ln(u^2 + d^2) in u (differentiate twice to
// check), up to terms linear in u, which cancel in edge_pair_integral's four-term sum.
double second_antiderivative(double u, double d) {
    const double r2 = u * u + d * d;
    if (r2 == 0.0) return 0.0;
    double value = 0.25 * (u * u - d * d) * std::log(r2) - 0.75 * u * u;
    if (d != 0.0) value += d * u * std::atan(u / d);
    return value;
}

// One edge of a rectangle's contour: along `axis`, from `start` to `end` in that coordinate, at
// `position` in the other two.
struct Edge {
    int axis;
    double start, end;
    Vec3 position;
};

// The two in-plane axes of a rectangle, the smaller first, and whether e_a x e_b is +e_axis.
struct PlaneAxes {
    int a, b;
    int handedness;
};

PlaneAxes plane_axes(int axis) {
    if (axis == 0) return {1, 2, +1};
    if (axis == 1) return {0, 2, -1};  // e_x x e_z = -e_y
    return {0, 1, +1};
}

// Corners counter-clockwise about e_a x e_b.
std::array<Vec3, 4> corners(const AxisRectangle& r) {
    const PlaneAxes p = plane_axes(r.axis);
    std::array<Vec3, 4> c{r.lo, r.lo, r.lo, r.lo};
    c[1][p.a] = r.hi[p.a];
    c[2][p.a] = r.hi[p.a];
    c[2][p.b] = r.hi[p.b];
    c[3][p.b] = r.hi[p.b];
    return c;
}

std::array<Edge, 4> edges(const AxisRectangle& r) {
    const std::array<Vec3, 4> c = corners(r);
    std::array<Edge, 4> e{};
    for (int k = 0; k < 4; ++k) {
        const Vec3& from = c[k];
        const Vec3& to = c[(k + 1) % 4];
        const int axis = from[0] != to[0] ? 0 : from[1] != to[1] ? 1 : 2;
        e[k] = {axis, from[axis], to[axis], from};
    }
    return e;
}

// One edge's term in Lambert's sum, for the edge from r0 to r1 (corners relative to the point):
// the angle it subtends times the cosine between the normal and its plane's normal. It changes
// sign with the edge's direction.
double lambert_edge_term(const Vec3& normal, const Vec3& r0, const Vec3& r1) {
    const Vec3 n = cross(r0, r1);
    const double n_length = length(n);
    if (n_length == 0.0) return 0.0;  // the point is on this edge's line: the edge subtends nothing
    return std::atan2(n_length, dot(r0, r1)) * dot(normal, n) / n_length;
}

// +1 when the corners' order is counter-clockwise about the rectangle's own normal.
int orientation(const AxisRectangle& r) { return plane_axes(r.axis).handedness * r.normal_sign; }

}  // namespace

double AxisRectangle::area() const {
    const PlaneAxes p = plane_axes(axis);
    return (hi[p.a] - lo[p.a]) * (hi[p.b] - lo[p.b]);
}

double edge_pair_integral(double a1, double a2, double b1, double b2, double d) {
    // Integrating f(u - v) over v then u: Phi(a2 - b1) - Phi(a1 - b1) - Phi(a2 - b2) + Phi(a1 - b2),
    // Phi'' = f = ln sqrt(. + d^2) = (1/2) ln(. + d^2).
    return second_antiderivative(a2 - b1, d) - second_antiderivative(a1 - b1, d) - second_antiderivative(a2 - b2, d) +
           second_antiderivative(a1 - b2, d);
}

double rectangle_form_factor(const AxisRectangle& from, const AxisRectangle& to) {
    if (from.axis == to.axis && from.lo[from.axis] == to.lo[to.axis]) return 0.0;
    double sum = 0.0;
    for (const Edge& e : edges(from)) {
        for (const Edge& f : edges(to)) {
            if (e.axis != f.axis) continue;  // perpendicular edges: de . df = 0
            const int p = (e.axis + 1) % 3, q = (e.axis + 2) % 3;
            const double dp = e.position[p] - f.position[p], dq = e.position[q] - f.position[q];
            const double d = std::sqrt(dp * dp + dq * dq);
            // de . df = sign(e) sign(f) du dv, with u and v running upwards.
            const double se = e.end > e.start ? 1.0 : -1.0, sf = f.end > f.start ? 1.0 : -1.0;
            sum += se * sf *
                   edge_pair_integral(std::fmin(e.start, e.end), std::fmax(e.start, e.end), std::fmin(f.start, f.end),
                                      std::fmax(f.start, f.end), d);
        }
    }
    return double(orientation(from) * orientation(to)) * sum / (2.0 * kPi * from.area());
}

double point_form_factor(const Vec3& point, const Vec3& normal, const AxisRectangle& to) {
    const std::array<Vec3, 4> c = corners(to);
    double sum = 0.0;
    for (int k = 0; k < 4; ++k) sum += lambert_edge_term(normal, c[k] - point, c[(k + 1) % 4] - point);
    // The sum is positive for corners counter-clockwise about the direction away from the point,
    // which for a rectangle facing the point is against its own normal.
    return -double(orientation(to)) * sum / (2.0 * kPi);
}

void grid_point_form_factors(const Vec3& point, const Vec3& normal, int axis, double plane, int normal_sign,
                             const std::vector<double>& nodes_a, const std::vector<double>& nodes_b, std::vector<double>& out) {
    const PlaneAxes p = plane_axes(axis);
    const std::size_t na = nodes_a.size(), nb = nodes_b.size();  // nodes; patches are one fewer each way
    auto node = [&](std::size_t i, std::size_t j) {
        Vec3 v;
        v[axis] = plane;
        v[p.a] = nodes_a[i];
        v[p.b] = nodes_b[j];
        return v - point;
    };
    std::vector<Vec3> r(na * nb);
    for (std::size_t i = 0; i < na; ++i)
        for (std::size_t j = 0; j < nb; ++j) r[i * nb + j] = node(i, j);
    // along_a(i, j): the edge from node (i, j) to (i + 1, j); along_b(i, j): from (i, j) to (i, j + 1).
    std::vector<double> along_a((na - 1) * nb), along_b(na * (nb - 1));
    for (std::size_t i = 0; i + 1 < na; ++i)
        for (std::size_t j = 0; j < nb; ++j) along_a[i * nb + j] = lambert_edge_term(normal, r[i * nb + j], r[(i + 1) * nb + j]);
    for (std::size_t i = 0; i < na; ++i)
        for (std::size_t j = 0; j + 1 < nb; ++j)
            along_b[i * (nb - 1) + j] = lambert_edge_term(normal, r[i * nb + j], r[i * nb + j + 1]);
    const double scale = -double(p.handedness * normal_sign) / (2.0 * kPi);
    out.resize((na - 1) * (nb - 1));
    for (std::size_t i = 0; i + 1 < na; ++i) {
        for (std::size_t j = 0; j + 1 < nb; ++j) {
            // Counter-clockwise about e_a x e_b, as corners(): (i,j) (i+1,j) (i+1,j+1) (i,j+1).
            const double sum = along_a[i * nb + j] + along_b[(i + 1) * (nb - 1) + j] - along_a[i * nb + j + 1] -
                               along_b[i * (nb - 1) + j];
            out[i * (nb - 1) + j] = scale * sum;
        }
    }
}

}  // namespace oracle
