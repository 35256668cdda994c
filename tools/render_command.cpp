#include "render_command.h"

#include <unistd.h>

#include <cstdio>
#include <exception>
#include <filesystem>
#include <iostream>
#include <sstream>

#include "cli_values.h"
#include "core/film/film.h"
#include "core/film/image_output.h"
#include "core/printable.h"
#include "core/scene.h"
#include "core/scene_file/scene_loader.h"
#include "kernels/isa/intersect_dispatch.h"
#include "kernels/memory_estimate.h"
#include "kernels/reference_integrator.h"

namespace wt {

CLI::App* add_render_command(CLI::App& app, RenderCommandOptions& o) {
    CLI::App* cmd = app.add_subcommand("render", "Render a scene file to one or more images");
    cmd->add_option("scene", o.scene_path, "Scene file (JSON)")->required()->check(CLI::ExistingFile);
    cmd->add_option("-o,--output", o.outputs,
                    "Output image; repeat for several. .exr/.hdr: linear float, .png/.jpg: sRGB 8-bit "
                    "(default: SCENE's name with .png, in the current directory)");
    cmd->add_option("--spp", o.spp, "Samples per pixel")->transform(decimal_integer(1, 1 << 20));
    cmd->add_option("--shadow-rays", o.shadow_rays, "Shadow rays per diffuse hit")->transform(decimal_integer(1, 1024));
    cmd->add_option("--width", o.width, "Image width in pixels")->transform(decimal_integer(1, 65536));
    cmd->add_option("--height", o.height, "Image height in pixels")->transform(decimal_integer(1, 65536));
    cmd->add_option("--seed", o.seed, "Random seed")->transform(decimal_integer(0, UINT64_MAX));
    cmd->add_option("--threads", o.render.threads, "Worker threads (default: one per hardware thread)")
        ->transform(decimal_integer(1, 1024));
    cmd->add_option("--integrator", o.integrator_name, "wavefront (fast) or reference (scalar per-path oracle)")
        ->check(CLI::IsMember({"wavefront", "reference"}));
    cmd->add_option("--triangle-test", o.triangle_test, "moller_trumbore (fast) or watertight (no leaks at shared edges)")
        ->check(CLI::IsMember({"moller_trumbore", "watertight"}));
    cmd->add_option("--sphere-test", o.sphere_test, "quadratic (fast) or cancellation_free (small and distant spheres)")
        ->check(CLI::IsMember({"quadratic", "cancellation_free"}));
    cmd->add_option("--fresnel", o.fresnel, "schlick (approximation) or exact (dielectric Fresnel equations)")
        ->check(CLI::IsMember({"schlick", "exact"}));
    cmd->add_option("--isa", o.isa_name, "Intersection kernels: scalar, sse4, avx2, avx512 or auto (the best this CPU runs)")
        ->check(CLI::IsMember({"auto", "scalar", "sse4", "avx2", "avx512"}));
    cmd->add_option("--accel", o.accel_name,
                    "Acceleration structure: auto (flat list for tiny scenes, else a BVH), bvh, or brute (flat list)")
        ->check(CLI::IsMember({"auto", "bvh", "brute"}));
    cmd->add_option("--bvh-width", o.render.bvh.node_width, "Children per BVH node: 4 or 8")->transform(decimal_integer(4, 8))->check(CLI::IsMember({4, 8}));
    cmd->add_option("--tile-size", o.render.tile_size, "Tile side in pixels")->transform(decimal_integer(1, 65536));
    cmd->add_option("--batch-paths", o.render.batch_paths, "Camera paths per wavefront batch")
        ->transform(decimal_integer(1, uint64_t(1) << 24));
    cmd->add_option("--debug-sample", o.debug_sample,
                    "X,Y,S: trace only sample S of pixel (X,Y) with the reference integrator and print every vertex");
    cmd->add_flag("-q,--quiet", o.quiet, "Print nothing but errors");
    return cmd;
}

namespace {

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

void print_vec(std::ostream& out, const glm::vec3& v) { out << "(" << v.x << ", " << v.y << ", " << v.z << ")"; }

int replay_sample(const Scene& scene, const RenderOptions& options, const DebugSample& d) {
    RayCounts counts;
    std::vector<PathVertexRecord> vertices;
    const uint32_t pixel = uint32_t(d.y) * uint32_t(scene.settings.width) + uint32_t(d.x);
    // The same hits either way; a big scene is replayed through a BVH so it takes no longer than a render would.
    Bvh bvh;
    BvhView tree;
    const int width = intersect_kernels(options.isa.value_or(best_supported_isa())).width;
    const bool use_bvh = resolve_accel(options.accel, scene.primitive_count(), width) == Accel::bvh;
    if (use_bvh) bvh = build_bvh(scene, options.bvh), tree = bvh_view(bvh);
    const glm::vec3 radiance = trace_reference_path(scene, pixel, d.sample, counts, &vertices, use_bvh ? &tree : nullptr);
    std::cout.precision(9);
    std::cout << "pixel (" << d.x << "," << d.y << ") sample " << d.sample << " seed " << scene.settings.seed << "\n";
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
        std::cout << "\n";
    }
    std::cout << "radiance ";
    print_vec(std::cout, radiance);
    std::cout << "\n";
    return 0;
}

void apply_overrides(const RenderCommandOptions& o, RenderSettings& s) {
    if (o.spp) s.spp = *o.spp;
    if (o.shadow_rays) s.shadow_rays = *o.shadow_rays;
    if (o.width) s.width = *o.width;
    if (o.height) s.height = *o.height;
    if (o.seed) s.seed = *o.seed;
    // The CLI checked membership already, so parsing cannot fail here.
    if (o.triangle_test) s.accuracy.triangles = *parse_triangle_test(*o.triangle_test);
    if (o.sphere_test) s.accuracy.spheres = *parse_sphere_test(*o.sphere_test);
    if (o.fresnel) s.accuracy.fresnel = *parse_fresnel_model(*o.fresnel);
}

}  // namespace

int run_render_command(RenderCommandOptions& o) {
    try {
        SceneDescription description = load_scene_file(o.scene_path);
        if (!o.quiet)
            for (const std::string& note : description.notes) std::cerr << "wavetrace: note: " << note << "\n";
        apply_overrides(o, description.settings);
        const RenderSettings settings = description.settings;
        const Scene scene = build_scene(description);
        description = SceneDescription();  // a big mesh's vertices and indices are in the scene now


        o.render.accel = *parse_accel(o.accel_name);  // CLI checked membership
        if (o.debug_sample)
            return replay_sample(scene, o.render, parse_debug_sample(*o.debug_sample, settings.width, settings.height));

        if (o.outputs.empty()) o.outputs.push_back(std::filesystem::path(o.scene_path).stem().string() + ".png");
        for (const std::string& out : o.outputs) check_output_path(out);
        o.render.integrator = o.integrator_name == "reference" ? Integrator::reference : Integrator::wavefront;
        if (o.isa_name != "auto") {
            o.render.isa = parse_isa(o.isa_name);
            if (!cpu_supports(*o.render.isa)) throw std::runtime_error("--isa " + o.isa_name + ": this CPU does not support it");
        }
        const std::string memory = memory_problem(estimate_render_memory(scene, o.render), available_memory_bytes());
        if (!memory.empty()) throw std::runtime_error(memory);
        Film film(settings.width, settings.height);
        const RenderResult result = render(scene, o.render, film);
        const std::vector<float> rgb = film.resolve();
        for (const std::string& out : o.outputs) write_image(out, settings.width, settings.height, rgb);

        if (!o.quiet) {
            const RayCounts& c = result.counts;
            const double secs = result.seconds;
            std::cout << "wavetrace: " << o.scene_path << " " << settings.width << "x" << settings.height << ", "
                      << settings.spp << " spp, " << settings.shadow_rays << " shadow rays, " << o.integrator_name
                      << " integrator" << (o.render.integrator == Integrator::wavefront ? std::string(" (") + isa_name(result.isa) + " kernels)" : "")
                      << ", " << result.threads << " thread" << (result.threads > 1 ? "s" : "") << "\n";
            std::cout.precision(3);
            std::cout << "  wall time        " << std::fixed << secs << " s\n";
            std::cout << "  samples/s        " << with_si_prefix(double(c.samples) / secs) << "\n";
            std::cout << "  rays/s           " << with_si_prefix(double(c.total_rays()) / secs) << " (camera "
                      << with_si_prefix(double(c.camera_rays)) << ", bounce " << with_si_prefix(double(c.bounce_rays))
                      << ", shadow " << with_si_prefix(double(c.shadow_rays)) << " rays)\n";
            std::cout << "  NaN/Inf samples  " << c.nonfinite_samples << "\n";
            if (result.accel == Accel::bvh) {
                const BvhStats& b = result.bvh;
                const double prims = double(std::max<std::size_t>(1, b.primitive_count));
                std::cout << "  BVH              " << o.render.bvh.node_width << "-wide, " << with_si_prefix(double(b.primitive_count))
                          << " primitives, " << with_si_prefix(double(b.node_count)) << " nodes, "
                          << with_si_prefix(double(b.leaf_count)) << " leaves, SAH cost " << b.sah_cost << ", built in "
                          << b.build_seconds << " s\n";
                std::cout << "  BVH memory       " << with_si_prefix(double(b.node_bytes + b.primitive_bytes)) << "B ("
                          << double(b.node_bytes) / prims << " B/primitive nodes, " << double(b.primitive_bytes) / prims
                          << " B/primitive leaf data)\n";
            } else {
                std::cout << "  acceleration     none (flat list of " << scene.primitive_count() << " primitives)\n";
            }
            for (const std::string& out : o.outputs) std::cout << "  wrote            " << out << "\n";
        }
        return 0;
    } catch (const std::exception& e) {
        std::cerr << "wavetrace: error: " << printable(e.what()) << "\n";
        return 1;
    }
}

}  // namespace wt
