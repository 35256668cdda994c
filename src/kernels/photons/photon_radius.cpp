#include "kernels/photons/photon_radius.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace wt {

namespace {

struct Bounds {
    glm::vec3 lo{INFINITY}, hi{-INFINITY};
    void add(const glm::vec3& p) { lo = glm::min(lo, p), hi = glm::max(hi, p); }
};

Bounds scene_bounds(const Scene& scene) {
    Bounds b;
    const TriangleSoA& t = scene.triangles;
    for (std::size_t i = 0; i < t.size(); ++i) {
        const glm::vec3 v0 = t.vertex0(i), e1 = t.edge1(i), e2 = t.edge2(i);
        b.add(v0), b.add(v0 + e1), b.add(v0 + e2);
        if (t.is_parallelogram(i)) b.add(v0 + e1 + e2);
    }
    const SphereSoA& s = scene.spheres;
    for (std::size_t i = 0; i < s.size(); ++i) {
        const glm::vec3 r(s.radius[i]);
        b.add(s.center(i) - r), b.add(s.center(i) + r);
    }
    return b;
}

// Photons per lookup at sample 0 grow with the disk's area in pixels; two pixels of radius
// (about twelve pixels of area) holds a few photons in a caustic at one light path per pixel
// while blurring it by less than the reconstruction a viewer would notice, and it shrinks as
// the samples grow.
constexpr double kAutomaticRadiusPixels = 2.0;

}  // namespace

// The automatic r_0: kAutomaticRadiusPixels times the footprint of a pixel on a surface facing
// the camera at the distance of the scene's centre (at least half the scene's diagonal, for a
// camera inside the scene): the caustic a camera sees through a flat mirror is at least about
// that far along the path, and a caustic blurred by a radius of a few of its pixels is still the
// caustic it would see. In scene units, so the radius follows the image's resolution and field
// of view, not an absolute size the scene's units would have to match.
double initial_photon_radius(const Scene& scene) {
    const Bounds b = scene_bounds(scene);
    if (!(b.lo.x <= b.hi.x)) return 1.0;  // no geometry: no photons either
    const double diagonal = glm::length(glm::dvec3(b.hi) - glm::dvec3(b.lo));
    const float requested = scene.settings.estimator.photon_radius;
    double radius = requested;
    if (!(requested > 0.0f)) {
        const Camera& camera = scene.camera;
        const float cx = 0.5f * float(scene.settings.width), cy = 0.5f * float(scene.settings.height);
        const glm::dvec3 a(camera.generate_ray(cx, cy).direction), c(camera.generate_ray(cx + 1.0f, cy).direction);
        const double pixel_angle = glm::length(c - a);
        const glm::dvec3 centre = 0.5 * (glm::dvec3(b.lo) + glm::dvec3(b.hi));
        const double distance = std::max(glm::length(centre - glm::dvec3(camera.eye())), 0.5 * diagonal);
        radius = kAutomaticRadiusPixels * pixel_angle * distance;
    }
    radius = std::min(radius, diagonal);
    // A flat scene point (diagonal 0) or a rounding to 0: any positive radius finds the same photons.
    return radius > 0.0 && std::isfinite(radius) ? radius : 1.0;
}

double PhotonRadiusSchedule::squared(uint32_t sample) {
    if (sample < sample_) sample_ = 0, squared_ = initial_squared_;
    for (; sample_ < sample; ++sample_) {
        const double i = double(sample_) + 1.0;  // Knaus and Zwicker's i, from 1
        squared_ = squared_ * (i + kPhotonRadiusAlpha) / (i + 1.0);
    }
    return squared_;
}

}  // namespace wt
