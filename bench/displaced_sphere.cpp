#include "displaced_sphere.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace wt::bench {

namespace {

constexpr double kPiD = 3.14159265358979323846;

// displacement() = (sin(a . p + a0) + sin(b . p + b0) + sin(c . p + c0)) / 3: frequencies of a
// few waves across the sphere, phases chosen so no two crests line up at a pole.
struct Wave {
    glm::dvec3 frequency;
    double phase;
};
constexpr int kWaveCount = 3;
const Wave kWaves[kWaveCount] = {{{5.0, 2.0, 0.0}, 0.5}, {{0.0, 7.0, -3.0}, 1.3}, {{4.0, 0.0, 6.0}, 2.1}};

// The gradient of displacement() as a function of 3D space; its part tangent to the unit
// sphere is the surface gradient.
glm::dvec3 displacement_gradient(const glm::dvec3& p) {
    glm::dvec3 gradient(0.0);
    for (const Wave& wave : kWaves) gradient += std::cos(glm::dot(wave.frequency, p) + wave.phase) * wave.frequency;
    return gradient / double(kWaveCount);
}

// The surface p(n) = centre + rho(n) n over unit directions n, rho = radius + amplitude * d(n).
// Its tangents are (grad_S rho . t) n + rho t for tangent directions t, so
// rho n - grad_S rho is normal to both: the analytic normal, outward since |grad_S rho| is
// small against rho.
struct SurfacePointAndNormal {
    glm::dvec3 position, normal;
};

SurfacePointAndNormal surface_at_direction(const DisplacedSphereShape& shape, const glm::dvec3& n) {
    const double rho = double(shape.radius) + double(shape.amplitude) * displacement(n.x, n.y, n.z);
    const glm::dvec3 gradient = double(shape.amplitude) * displacement_gradient(n);
    const glm::dvec3 surface_gradient = gradient - glm::dot(gradient, n) * n;
    return {glm::dvec3(shape.centre) + rho * n, glm::normalize(rho * n - surface_gradient)};
}

void check_shape(const DisplacedSphereShape& shape) {
    if (shape.segments_u < 3) throw std::invalid_argument("displaced sphere: segments_u must be at least 3, got " + std::to_string(shape.segments_u));
    if (shape.segments_v < 2) throw std::invalid_argument("displaced sphere: segments_v must be at least 2, got " + std::to_string(shape.segments_v));
    if (!(shape.radius > 0.0f) || !(shape.amplitude >= 0.0f) || !(shape.amplitude < shape.radius))
        throw std::invalid_argument("displaced sphere: need radius > 0 and 0 <= amplitude < radius, got radius " +
                                    std::to_string(shape.radius) + ", amplitude " + std::to_string(shape.amplitude));
}

}  // namespace

double displacement(double x, double y, double z) {
    const glm::dvec3 p(x, y, z);
    double sum = 0.0;
    for (const Wave& wave : kWaves) sum += std::sin(glm::dot(wave.frequency, p) + wave.phase);
    return sum / double(kWaveCount);
}

std::size_t displaced_sphere_triangle_count(const DisplacedSphereShape& shape) {
    return 2 * std::size_t(shape.segments_u) * std::size_t(shape.segments_v - 1);
}

std::size_t displaced_sphere_vertex_count(const DisplacedSphereShape& shape) {
    return 2 + std::size_t(shape.segments_u) * std::size_t(shape.segments_v - 1);
}

TriangleMesh displaced_sphere(const DisplacedSphereShape& shape, uint32_t material) {
    check_shape(shape);
    const uint32_t u_count = uint32_t(shape.segments_u);
    const uint32_t ring_count = uint32_t(shape.segments_v - 1);
    TriangleMesh mesh;
    mesh.material = material;
    mesh.vertices.reserve(displaced_sphere_vertex_count(shape));
    mesh.normals.reserve(displaced_sphere_vertex_count(shape));
    mesh.triangles.reserve(displaced_sphere_triangle_count(shape));
    auto add_vertex = [&](const glm::dvec3& direction) {
        const SurfacePointAndNormal point = surface_at_direction(shape, direction);
        mesh.vertices.push_back(glm::vec3(point.position));
        mesh.normals.push_back(glm::vec3(point.normal));
    };

    add_vertex({0.0, 0.0, 1.0});
    for (uint32_t j = 1; j <= ring_count; ++j) {
        const double theta = kPiD * double(j) / double(shape.segments_v);
        for (uint32_t i = 0; i < u_count; ++i) {
            const double phi = 2.0 * kPiD * double(i) / double(shape.segments_u);
            add_vertex({std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)});
        }
    }
    add_vertex({0.0, 0.0, -1.0});

    // Seen from outside with north up, azimuth grows to the right: a quad's corners
    // upper-left a, upper-right b, lower-left c, lower-right d make the counter-clockwise
    // triangles (a, c, d) and (a, d, b); at the poles the quad's pole side collapses to a point.
    const uint32_t north = 0;
    const uint32_t south = uint32_t(mesh.vertices.size() - 1);
    auto ring_vertex = [&](uint32_t ring, uint32_t i) { return 1 + (ring - 1) * u_count + i % u_count; };
    for (uint32_t i = 0; i < u_count; ++i) mesh.triangles.push_back({north, ring_vertex(1, i), ring_vertex(1, i + 1)});
    for (uint32_t j = 1; j < ring_count; ++j) {
        for (uint32_t i = 0; i < u_count; ++i) {
            const uint32_t a = ring_vertex(j, i), b = ring_vertex(j, i + 1);
            const uint32_t c = ring_vertex(j + 1, i), d = ring_vertex(j + 1, i + 1);
            mesh.triangles.push_back({a, c, d});
            mesh.triangles.push_back({a, d, b});
        }
    }
    for (uint32_t i = 0; i < u_count; ++i) mesh.triangles.push_back({ring_vertex(ring_count, i), south, ring_vertex(ring_count, i + 1)});
    return mesh;
}

DisplacedSphereShape benchmark_sphere(int segments_u, int segments_v) {
    DisplacedSphereShape shape;
    shape.segments_u = segments_u;
    shape.segments_v = segments_v;
    shape.centre = kBenchmarkSphereCentre;
    shape.radius = 2.0f;
    shape.amplitude = 0.2f;
    return shape;
}

}  // namespace wt::bench
