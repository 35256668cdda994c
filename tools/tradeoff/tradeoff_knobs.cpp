#include "tools/tradeoff/tradeoff_knobs.h"

#include <sstream>
#include <stdexcept>

namespace wt {

namespace {

// The integer knobs' values are written in the table, so stoi cannot fail on them.
void set_shadow_rays(RenderSettings& s, const std::string& v) { s.shadow_rays = std::stoi(v); }
void set_rr_start(RenderSettings& s, const std::string& v) { s.rr_start_bounce = std::stoi(v); }
void set_max_bounces(RenderSettings& s, const std::string& v) { s.max_bounces = std::stoi(v); }
void set_fresnel(RenderSettings& s, const std::string& v) { s.accuracy.fresnel = *parse_fresnel_model(v); }
void set_multiple_scattering(RenderSettings& s, const std::string& v) {
    s.accuracy.multiple_scattering = *parse_multiple_scattering(v);
}
void set_triangle_test(RenderSettings& s, const std::string& v) { s.accuracy.triangles = *parse_triangle_test(v); }
void set_sphere_test(RenderSettings& s, const std::string& v) { s.accuracy.spheres = *parse_sphere_test(v); }
void set_sampler(RenderSettings& s, const std::string& v) { s.estimator.sampler = *parse_sampler(v); }
void set_light_sampling(RenderSettings& s, const std::string& v) { s.estimator.light_sampling = *parse_light_sampling(v); }
void set_light_selection(RenderSettings& s, const std::string& v) { s.estimator.light_selection = *parse_light_selection(v); }
void set_caustics(RenderSettings& s, const std::string& v) { s.estimator.caustics = *parse_caustic_paths(v); }
void set_light_paths(RenderSettings& s, const std::string& v) { s.estimator.light_paths_per_pixel = std::stof(v); }
void set_clamp(RenderSettings& s, const std::string& v) { s.estimator.clamp_indirect = std::stof(v); }
void set_adaptive_threshold(RenderSettings& s, const std::string& v) { s.adaptive.threshold = std::stof(v); }
void set_adaptive_min_spp(RenderSettings& s, const std::string& v) { s.adaptive.min_spp = std::stoi(v); }

std::string shadow_rays(const RenderSettings& s) { return std::to_string(s.shadow_rays); }
std::string rr_start(const RenderSettings& s) { return std::to_string(s.rr_start_bounce); }
std::string max_bounces(const RenderSettings& s) { return std::to_string(s.max_bounces); }
std::string fresnel(const RenderSettings& s) { return name_of(s.accuracy.fresnel); }
std::string multiple_scattering(const RenderSettings& s) { return name_of(s.accuracy.multiple_scattering); }
std::string triangle_test(const RenderSettings& s) { return name_of(s.accuracy.triangles); }
std::string sphere_test(const RenderSettings& s) { return name_of(s.accuracy.spheres); }
std::string sampler(const RenderSettings& s) { return name_of(s.estimator.sampler); }
std::string light_sampling(const RenderSettings& s) { return name_of(s.estimator.light_sampling); }
std::string light_selection(const RenderSettings& s) { return name_of(s.estimator.light_selection); }
std::string caustics(const RenderSettings& s) { return name_of(s.estimator.caustics); }
std::string shortest(float v) {
    std::ostringstream out;  // 4 -> "4", 0.05f -> "0.05", as the table writes them
    out << v;
    return out.str();
}
std::string light_paths(const RenderSettings& s) { return shortest(s.estimator.light_paths_per_pixel); }
std::string clamp(const RenderSettings& s) { return shortest(s.estimator.clamp_indirect); }
std::string adaptive_threshold(const RenderSettings& s) { return shortest(s.adaptive.threshold); }
std::string adaptive_min_spp(const RenderSettings& s) { return std::to_string(s.adaptive.min_spp); }

}  // namespace

const std::vector<Knob>& tradeoff_knobs() {
    // Russian roulette's survival threshold (0.95) is not a setting, so it is not here.
    static const std::vector<Knob> knobs = {
        {"shadow_rays", {"1", "2", "3", "4", "8"}, false, set_shadow_rays, shadow_rays},
        {"rr_start_bounce", {"0", "1", "3", "5", "8"}, false, set_rr_start, rr_start},
        {"max_bounces", {"2", "4", "8", "16", "64"}, true, set_max_bounces, max_bounces},
        {"fresnel", {"schlick", "exact"}, true, set_fresnel, fresnel},
        // A model, not an estimator: kulla_conty converges to another image (rough metals
        // brighter), which against a single-scattering reference shows as a floor.
        {"multiple_scattering", {"none", "kulla_conty"}, true, set_multiple_scattering, multiple_scattering},
        {"triangle_test", {"moller_trumbore", "watertight"}, true, set_triangle_test, triangle_test},
        {"sphere_test", {"quadratic", "cancellation_free"}, true, set_sphere_test, sphere_test},
        {"sampler", {"independent", "stratified", "sobol"}, false, set_sampler, sampler},
        {"light_sampling", {"nee", "mis"}, false, set_light_sampling, light_sampling},
        // All three unbiased: which emitter a light sample goes to changes the noise, not the mean.
        {"light_selection", {"area", "power", "bvh"}, false, set_light_selection, light_selection},
        // 0 is off; the clamp trades bias (the mean drops where caustics are) for variance.
        {"clamp_indirect", {"0", "1", "4", "16"}, true, set_clamp, clamp},
        // path and light_tracing are unbiased; photons are consistent (the disk kernel blurs the
        // caustic by a radius that shrinks with the spp), so the floor is reported.
        {"caustics", {"path", "light_tracing", "photons"}, true, set_caustics, caustics},
        // Only changes anything with light tracing: its work per sample against its noise.
        {"light_paths_per_pixel", {"0.25", "0.5", "1", "2", "4"}, false, set_light_paths, light_paths},
        // 0 is off. Stopping on an estimate of the error can bias (a heavy-tailed pixel whose
        // rare bright paths have not shown yet looks converged), so the floor is reported.
        {"adaptive_threshold", {"0", "0.03", "0.06", "0.12", "0.25"}, true, set_adaptive_threshold, adaptive_threshold},
        // Changes nothing unless the scene has an adaptive_threshold: sweep it on such a scene.
        {"adaptive_min_spp", {"4", "16", "64"}, true, set_adaptive_min_spp, adaptive_min_spp},
    };
    return knobs;
}

const Knob& tradeoff_knob(const std::string& name) {
    std::string known;
    for (const Knob& k : tradeoff_knobs()) {
        if (name == k.name) return k;
        known += std::string(known.empty() ? "" : ", ") + k.name;
    }
    throw std::invalid_argument("no knob named '" + name + "' (known: " + known + ")");
}

}  // namespace wt
