#include "tools/render/debug_light_path.h"

#include <iostream>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "kernels/caustics/light_path.h"
#include "tools/render/replay_accel.h"

namespace wt {

namespace {
void print_vec(std::ostream& out, const glm::vec3& v) { out << "(" << v.x << ", " << v.y << ", " << v.z << ")"; }
}  // namespace

DebugLightPath parse_debug_light_path(const std::string& text, const Scene& scene) {
    if (!scene.light_traces_caustics)
        throw std::runtime_error("--debug-light-path: this render traces no light paths (caustics \"light_tracing\" or "
                                 "\"photons\", and a scene with lights and a mirror or glass surface)");
    char comma = 0;
    long long index = -1, sample = -1;
    std::istringstream in(text);
    in >> index >> comma >> sample;
    if (!in || comma != ',' || !(in >> std::ws).eof())
        throw std::runtime_error("--debug-light-path: expected I,S (two integers), got '" + text + "'");
    const uint64_t paths = light_paths_per_sample(scene.settings);
    if (index < 0 || uint64_t(index) >= paths)
        throw std::runtime_error("--debug-light-path: path " + std::to_string(index) + " is not one of the " +
                                 std::to_string(paths) + " light paths of a sample");
    if (sample < 0 || sample > 0xffffffffLL)
        throw std::runtime_error("--debug-light-path: sample index out of range: " + std::to_string(sample));
    return {uint64_t(index), uint32_t(sample)};
}

int replay_light_path(const Scene& scene, const RenderOptions& options, const DebugLightPath& d) {
    const ReplayAccel accel(scene, options);
    const LightPathTracer tracer(scene, accel.view());
    RayCounts counts;
    std::vector<CameraSplat> splats;
    std::vector<LightPathVertexRecord> vertices;
    tracer.trace(d.index, d.sample, counts, splats, &vertices);
    const uint32_t image_width = uint32_t(scene.settings.width);
    std::cout.precision(9);
    std::cout << "light path " << d.index << " of sample " << d.sample << " seed " << scene.settings.seed << "\n";
    for (const LightPathVertexRecord& v : vertices) {
        std::cout << "  vertex " << v.vertex << ": t=" << v.hit.t << " prim " << v.hit.prim << " material '"
                  << scene.materials[v.material].name << "' at ";
        print_vec(std::cout, v.position);
        std::cout << " carrying ";
        print_vec(std::cout, v.carried);
        if (v.splat) {
            std::cout << "\n    camera connection to pixel (" << v.splat->pixel % image_width << ","
                      << v.splat->pixel / image_width << ") ";
            print_vec(std::cout, v.splat->value);
            std::cout << (v.connection_blocked ? " blocked" : " splatted");
        }
        std::cout << "\n";
    }
    std::cout << splats.size() << " splat" << (splats.size() == 1 ? "" : "s") << "\n";
    return 0;
}

}  // namespace wt
