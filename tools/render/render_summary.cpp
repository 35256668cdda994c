#include "tools/render/render_summary.h"

#include <algorithm>
#include <iomanip>
#include <ostream>
#include <sstream>

#include "kernels/adaptive/adaptive_summary.h"
#include "kernels/isa/intersect_dispatch.h"
#include "kernels/caustics/photon_memory.h"
#include "kernels/memory_estimate.h"

namespace wt {

std::string with_si_prefix(double value) {
    std::ostringstream s;
    s.precision(3);
    if (value >= 1e9) s << std::fixed << value / 1e9 << " G";
    else if (value >= 1e6) s << std::fixed << value / 1e6 << " M";
    else if (value >= 1e3) s << std::fixed << value / 1e3 << " k";
    else if (value == double(uint64_t(value))) s << uint64_t(value);
    else s << std::fixed << value;
    return s.str();
}

namespace {

const char* stop_description(StopReason reason) {
    switch (reason) {
    case StopReason::finished: return "finished";
    case StopReason::time_limit: return "stopped by the time limit";
    case StopReason::interrupted: return "interrupted";
    case StopReason::observer: return "stopped";
    }
    return "";
}

}  // namespace

void print_render_summary(std::ostream& out, const RenderSummary& m) {
    const RenderSettings& settings = m.scene->settings;
    const RenderResult& result = m.result;
    const RayCounts& c = result.counts;
    const double secs = result.seconds;
    out << "wavetrace: " << m.scene_path << " " << settings.width << "x" << settings.height << ", " << m.film_spp
        << " spp, " << settings.shadow_rays << " shadow ray" << (settings.shadow_rays > 1 ? "s" : "") << ", "
        << m.integrator_name << " integrator"
        << (m.options->integrator == Integrator::wavefront ? std::string(" (") + isa_name(result.isa) + " kernels)" : "")
        << ", " << result.threads << " thread" << (result.threads > 1 ? "s" : "") << "\n";
    out.precision(3);
    out << "  wall time        " << std::fixed << secs << " s\n";
    out << "  passes           " << m.progressive.passes << ", " << stop_description(m.progressive.reason);
    if (m.film_spp < uint32_t(settings.spp)) out << " at " << m.film_spp << " of " << settings.spp << " spp";
    out << "\n";
    out << "  samples/s        " << with_si_prefix(secs > 0 ? double(c.samples) / secs : 0.0) << "\n";
    out << "  rays/s           " << with_si_prefix(secs > 0 ? double(c.total_rays()) / secs : 0.0) << " (camera "
        << with_si_prefix(double(c.camera_rays)) << ", bounce " << with_si_prefix(double(c.bounce_rays)) << ", shadow "
        << with_si_prefix(double(c.shadow_rays)) << " rays)\n";
    out << "  NaN/Inf samples  " << c.nonfinite_samples << "\n";
    if (m.scene->light_traces_caustics) {
        const double paths = double(std::max<uint64_t>(1, c.light_paths));
        out << "  light tracing    " << with_si_prefix(double(c.light_paths)) << " light paths ("
            << settings.estimator.light_paths_per_pixel << " per pixel and sample), " << double(c.light_rays) / paths
            << " rays and " << double(c.camera_connections) / paths << " camera connections each, "
            << c.dropped_splats << " NaN/Inf splats\n";
        if (m.scene->merges_photons)
            out << "  photons          " << with_si_prefix(double(c.photons)) << " (" << double(c.photons) / paths
                << " per light path; the memory estimate expected " << expected_photons_per_light_path(*m.scene) << ")\n";
    }
    if (m.adaptive && !m.adaptive->empty()) {
        const AdaptiveSummary a = summarize_adaptive(*m.adaptive);
        out << "  adaptive         threshold " << std::defaultfloat << settings.adaptive.threshold << ", min "
            << settings.adaptive.min_spp << " spp: " << a.stopped << " of " << a.pixels << " pixels stopped ("
            << std::fixed << std::setprecision(1) << 100.0 * double(a.stopped) / double(std::max<uint64_t>(1, a.pixels))
            << " %), mean " << a.mean_spp << " spp\n";
        out.precision(3);
    }
    out << "  geometry         " << geometry_memory_line(*m.scene) << "\n";
    if (result.accel == Accel::bvh) {
        const BvhStats& b = result.bvh;
        const double prims = double(std::max<std::size_t>(1, b.primitive_count));
        out << "  BVH              " << m.options->bvh.node_width << "-wide, " << with_si_prefix(double(b.primitive_count))
            << " primitives, " << with_si_prefix(double(b.node_count)) << " nodes, " << with_si_prefix(double(b.leaf_count))
            << " leaves, SAH cost " << b.sah_cost << ", built in " << b.build_seconds << " s"
            << (b.beside_count > 0 ? "; " + std::to_string(b.beside_count) + " parallelograms tested beside it" : std::string())
            << "\n";
        out << "  BVH memory       " << with_si_prefix(double(b.node_bytes + b.primitive_bytes)) << "B ("
            << double(b.node_bytes) / prims << " B/primitive nodes, " << double(b.primitive_bytes) / prims
            << " B/primitive leaf data)\n";
        if (result.instance_count > 0) {
            const SceneInstances& in = m.scene->instances;
            uint64_t stored = 0;
            for (const InstancedMesh& mesh : in.meshes) stored += mesh.triangles.size();
            out << "  instances        " << result.instance_count << " of " << in.meshes.size() << " mesh"
                << (in.meshes.size() == 1 ? "" : "es") << ", " << with_si_prefix(double(stored)) << " triangles stored once, "
                << with_si_prefix(double(in.triangle_count)) << " placed; meshes' trees "
                << with_si_prefix(double(result.instanced_mesh_bytes)) << "B, "
                << double(result.instance_bytes) / double(result.instance_count) << " B per instance\n";
        }
    } else {
        out << "  acceleration     none (flat list of " << m.scene->primitive_count() << " primitives)\n";
    }
    for (const std::string& path : m.written) out << "  wrote            " << path << "\n";
}

}  // namespace wt
