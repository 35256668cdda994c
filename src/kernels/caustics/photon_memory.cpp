#include "kernels/caustics/photon_memory.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "core/sampling/sampling.h"
#include "kernels/caustics/light_path.h"
#include "kernels/photons/photon.h"
#include "kernels/photons/photon_maps.h"

namespace wt {
namespace {

float largest(const glm::vec3& c) { return std::max(c.x, std::max(c.y, c.z)); }

// The share of light a surface of `m` sends on: what the roulette's survival follows.
float reflectance(const Material& m) {
    switch (m.type) {
        case MaterialType::lambertian:
        case MaterialType::oren_nayar: return largest(m.albedo);
        case MaterialType::mirror: return largest(m.reflectance);
        case MaterialType::glass:
        case MaterialType::rough_glass: return 1.0f;
        case MaterialType::conductor:
        case MaterialType::rough_conductor: return m.eta.x > 0.0f ? 1.0f : largest(m.f0);
        case MaterialType::principled: return std::max(largest(m.base_color), 0.04f);
    }
    return 1.0f;
}

struct SurfaceAverages {
    double survival = 0.95;       // the share of light a vertex sends on, capped as the roulette caps it
    double specular_share = 1.0;  // of the surface area: mirrors, smooth glass and metals
};

// Both averaged over the scene's surface area.
SurfaceAverages surface_averages(const Scene& scene) {
    double area = 0.0, survival = 0.0, specular = 0.0;
    auto add = [&](double a, uint32_t material) {
        if (!(a > 0.0) || !std::isfinite(a)) return;
        const Material& m = scene.materials[material];
        area += a;
        survival += a * std::min(0.95, double(reflectance(m)));
        if (m.is_specular()) specular += a;
    };
    const TriangleSoA& t = scene.triangles;
    for (std::size_t i = 0; i < t.size(); ++i)
        add(double(glm::length(glm::cross(t.edge1(i), t.edge2(i)))) * (t.is_parallelogram(i) ? 1.0 : 0.5), t.material[i]);
    const SphereSoA& s = scene.spheres;
    for (std::size_t i = 0; i < s.size(); ++i) add(4.0 * double(kPi) * double(s.radius[i]) * double(s.radius[i]), s.material[i]);
    if (!(area > 0.0)) return {};
    return {survival / area, specular / area};
}

}  // namespace

uint64_t photon_batch_light_paths(uint64_t batch_paths, uint64_t light_paths_per_sample) {
    return uint64_t(PhotonMaps::samples_per_batch(batch_paths, light_paths_per_sample)) * light_paths_per_sample;
}

double expected_photons_per_light_path(const Scene& scene) {
    // A light path goes on past its first vertex only from a specular one (light_path.cpp,
    // at_vertex: a diffuse first bounce is the camera paths' direct light), which it meets with
    // about the specular share of the surface area. Vertices 2 .. max_bounces - 2 can hold a
    // photon (photon_at), and the path reaches every vertex up to the first the roulette plays
    // at, v = rr_start_bounce + 1. Its throughput there is about q^(v - 1) (one reflection per
    // vertex after the specular one), so it goes on with min(0.95, q^(v - 1)); divided by that,
    // the throughput is about 1 again, and each next vertex goes on with q.
    const int first = 2, last = scene.settings.max_bounces - 2;
    if (last < first) return 0.0;
    const SurfaceAverages a = surface_averages(scene);
    const double q = a.survival;
    const int sure = std::clamp(scene.settings.rr_start_bounce + 1, first - 1, last);  // the last vertex reached for sure
    const int tail = last - sure;                                                     // vertices after it
    const double first_survival = std::min(0.95, std::pow(q, double(std::max(sure - 1, 0))));
    // first_survival (1 + q + ... + q^(tail - 1)).
    const double after = q < 1.0 ? first_survival * (1.0 - std::pow(q, double(tail))) / (1.0 - q) : first_survival * double(tail);
    return a.specular_share * (double(sure - first + 1) + after);
}

double photon_peak_bytes() {
    // List: a vector grown by doubling holds up to twice its photons. Grid: the photon, its
    // index, up to two bucket starts (buckets are a power of two >= photons) and the build's
    // bucket of each photon.
    return 2.0 * sizeof(Photon) + sizeof(Photon) + sizeof(uint32_t) + 2.0 * sizeof(uint32_t) + sizeof(uint32_t);
}

double photon_batch_bytes(const Scene& scene, uint64_t batch_paths) {
    const uint64_t paths = photon_batch_light_paths(batch_paths, light_paths_per_sample(scene.settings));
    return double(paths) * expected_photons_per_light_path(scene) * photon_peak_bytes();
}

}  // namespace wt
