#pragma once
// The camera importance's integral over the directions from one point, for the camera tests:
// sum over a uniform grid of the sphere of directions of importance x solid angle. For any
// camera point it is width x height, one per pixel.

#include <cmath>

#include <glm/vec3.hpp>

namespace wt::test {

// `film_point(direction)`: the camera's FilmPoint (or nothing) for the point one unit along it.
template <typename FilmPointOf>
double importance_over_the_sphere(FilmPointOf film_point, int n = 1000) {
    double total = 0.0;
    for (int a = 0; a < n; ++a)
        for (int b = 0; b < n; ++b) {
            const double z = 1.0 - 2.0 * (a + 0.5) / n, phi = 2.0 * M_PI * (b + 0.5) / n, s = std::sqrt(1.0 - z * z);
            const glm::vec3 dir(float(s * std::cos(phi)), float(s * std::sin(phi)), float(z));
            if (const auto p = film_point(dir)) total += double(p->importance) * 4.0 * M_PI / (double(n) * n);
        }
    return total;
}

}  // namespace wt::test
