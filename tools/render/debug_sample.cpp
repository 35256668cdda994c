#include "tools/render/debug_sample.h"

#include <iostream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "kernels/caustics/light_path.h"
#include "kernels/photons/photon_maps.h"
#include "kernels/reference_integrator.h"
#include "tools/render/replay_accel.h"

namespace wt {

namespace {

void print_vec(std::ostream& out, const glm::vec3& v) { out << "(" << v.x << ", " << v.y << ", " << v.z << ")"; }

}  // namespace

DebugSample parse_debug_sample(const std::string& text, int width, int height) {
    DebugSample d;
    char comma1 = 0, comma2 = 0;
    long long x = -1, y = -1, s = -1;
    std::istringstream in(text);
    in >> x >> comma1 >> y >> comma2 >> s;
    if (!in || comma1 != ',' || comma2 != ',' || !(in >> std::ws).eof())
        throw std::runtime_error("--debug-sample: expected X,Y,S (three integers), got '" + text + "'");
    if (x < 0 || x >= width || y < 0 || y >= height)
        throw std::runtime_error("--debug-sample: pixel (" + std::to_string(x) + "," + std::to_string(y) +
                                 ") is outside the " + std::to_string(width) + "x" + std::to_string(height) + " image");
    if (s < 0 || s > 0xffffffffLL) throw std::runtime_error("--debug-sample: sample index out of range: " + std::to_string(s));
    d.x = int(x), d.y = int(y), d.sample = uint32_t(s);
    return d;
}

int replay_sample(const Scene& scene, const RenderOptions& options, const DebugSample& d) {
    RayCounts counts;
    std::vector<PathVertexRecord> vertices;
    const uint32_t pixel = uint32_t(d.y) * uint32_t(scene.settings.width) + uint32_t(d.x);
    const ReplayAccel accel(scene, options);
    std::cout.precision(9);
    std::cout << "pixel (" << d.x << "," << d.y << ") sample " << d.sample << " seed " << scene.settings.seed << "\n";
    // With photons, the sample's photon map first: every light path of the sample, one at a time,
    // as one list (the render's lists in item order are the same photons in the same order).
    std::unique_ptr<PhotonMaps> photons;
    if (scene.merges_photons) {
        photons = std::make_unique<PhotonMaps>(scene);
        photons->start_batch(d.sample, d.sample + 1, 1);
        const LightPathTracer tracer(scene, accel.view(), true);
        std::vector<CameraSplat> splats;
        const uint64_t paths = light_paths_per_sample(scene.settings);
        for (uint64_t i = 0; i < paths; ++i, splats.clear())
            tracer.trace(i, d.sample, counts, splats, nullptr, &photons->photons(0));
        const PhotonGrid& map = photons->map(d.sample);
        std::cout << "photon map of sample " << d.sample << ": " << map.size() << " photons from " << paths
                  << " light paths, radius " << map.radius() << "\n";
    }
    const glm::vec3 radiance = trace_reference_path(scene, pixel, d.sample, counts, &vertices, accel.view(), nullptr,
                                                    photons.get());
    for (const PathVertexRecord& v : vertices) {
        std::cout << "  bounce " << v.bounce << ": t=" << v.hit.t << " prim " << v.hit.prim << " material '"
                  << scene.materials[v.material].name << "' at ";
        print_vec(std::cout, v.position);
        std::cout << " normal ";
        print_vec(std::cout, v.normal);
        if (v.shading_normal != v.normal) {
            std::cout << " shading normal ";
            print_vec(std::cout, v.shading_normal);
        }
        std::cout << "\n    throughput ";
        print_vec(std::cout, v.throughput);
        std::cout << " emission added ";
        print_vec(std::cout, v.emission_added);
        std::cout << " shadow rays " << v.shadow_rays_unoccluded << "/" << v.shadow_rays_traced << " unblocked, direct added ";
        print_vec(std::cout, v.direct_added);
        if (v.photon_radius > 0.0f) {
            std::cout << "\n    photons gathered " << v.photons_gathered << " within radius " << v.photon_radius << ", added ";
            print_vec(std::cout, v.photons_added);
        }
        std::cout << "\n";
    }
    std::cout << "radiance ";
    print_vec(std::cout, radiance);
    std::cout << "\n";
    return 0;
}

}  // namespace wt
