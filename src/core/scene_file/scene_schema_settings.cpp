#include <cmath>
#include <cstdint>

#include <glm/geometric.hpp>

#include "core/camera.h"
#include "core/scene_file/scene_schema.h"

// The camera and render sections.

namespace wt {

CameraDescription read_camera(const Reader& in, const Json& j, const std::string& path) {
    in.expect_object(j, path);
    in.check_keys(j, path, {"eye", "look_at", "up", "fov_degrees"});
    CameraDescription camera;
    camera.eye = in.vec3(in.required(j, "eye", path), member_path(path, "eye"));
    camera.look_at = in.vec3(in.required(j, "look_at", path), member_path(path, "look_at"));
    if (const Json* up = in.optional(j, "up")) camera.up = in.vec3(*up, member_path(path, "up"));
    if (const Json* fov = in.optional(j, "fov_degrees")) {
        const std::string fov_path = member_path(path, "fov_degrees");
        camera.fov_degrees = in.number(*fov, fov_path);
        if (!(camera.fov_degrees > 0.0f && camera.fov_degrees < 180.0f))
            in.fail(fov_path, "must be in (0, 180) degrees, exclusive, got " + describe(*fov));
    }

    // The camera basis is normalize(look_at - eye) and normalize(cross(forward, up)); both must exist.
    const glm::dvec3 forward = glm::dvec3(camera.look_at) - glm::dvec3(camera.eye);
    if (glm::length(forward) == 0.0)
        in.fail(member_path(path, "look_at"),
                "must differ from camera.eye, got " + format_vec3(camera.look_at) + " for both");
    const glm::dvec3 up = camera.up;
    if (glm::length(up) == 0.0) in.fail(member_path(path, "up"), "must be non-zero, got [0, 0, 0]");
    const double sine = glm::length(glm::cross(glm::normalize(forward), glm::normalize(up)));
    if (sine <= 1e-6)
        in.fail(member_path(path, "up"), "must not be parallel to the view direction (look_at - eye = " +
                                             format_vec3(forward) + "), got " + format_vec3(up));

    // The renderer builds the basis in float, where 1e-30 squares to 0 and 1e20 to infinity:
    // a basis that is not unit length there renders a black image, so refuse it here.
    const auto unit = [](const glm::vec3& v) {
        const float length = glm::length(v);
        return std::isfinite(length) && std::fabs(length - 1.0f) < 1e-3f;
    };
    const glm::vec3 difference = camera.look_at - camera.eye;
    if (!std::isfinite(difference.x) || !std::isfinite(difference.y) || !std::isfinite(difference.z))
        in.fail(member_path(path, "look_at"), "look_at - eye overflows a 32-bit float (eye " + format_vec3(camera.eye) +
                                                  ", look_at " + format_vec3(camera.look_at) + ")");
    const CameraBasis basis = camera_basis(camera);
    if (!unit(basis.forward))
        in.fail(member_path(path, "look_at"), "look_at - eye = " + format_vec3(difference) +
                                                  " cannot be normalised in 32-bit float (too short or too long)");
    if (!unit(basis.right) || !unit(basis.up))
        in.fail(member_path(path, "up"), "cannot be used in 32-bit float: cross(forward, up) cannot be normalised "
                                         "(up too short or too long), got " + format_vec3(camera.up));
    return camera;
}

RenderSettings read_render(const Reader& in, const Json& j, const std::string& path) {
    in.expect_object(j, path);
    in.check_keys(j, path, {"width", "height", "spp", "shadow_rays", "seed", "max_bounces", "rr_start_bounce",
                            "triangle_test", "sphere_test", "fresnel", "sampler", "light_sampling", "clamp_indirect",
                            "caustics", "light_paths_per_pixel", "photon_radius", "adaptive_threshold",
                            "adaptive_min_spp"});
    RenderSettings s;
    const auto read_int = [&](const char* key, int& field, uint64_t lo, uint64_t hi) {
        if (const Json* v = in.optional(j, key)) field = int(in.integer(*v, member_path(path, key), lo, hi));
    };
    read_int("width", s.width, 1, 65536);
    read_int("height", s.height, 1, 65536);
    read_int("spp", s.spp, 1, uint64_t(1) << 20);
    read_int("shadow_rays", s.shadow_rays, 1, 1024);
    read_int("max_bounces", s.max_bounces, 1, 1024);
    read_int("rr_start_bounce", s.rr_start_bounce, 0, INT32_MAX);
    read_int("adaptive_min_spp", s.adaptive.min_spp, adaptive_min_spp_lowest, uint64_t(1) << 20);
    if (const Json* seed = in.optional(j, "seed")) s.seed = in.integer(*seed, member_path(path, "seed"), 0, UINT64_MAX);
    const auto read_choice = [&](const char* key, auto& field, auto parse, const char* allowed) {
        const Json* v = in.optional(j, key);
        if (!v) return;
        const std::string key_path = member_path(path, key);
        const auto parsed = parse(in.text(*v, key_path));
        if (!parsed) in.fail(key_path, std::string("must be one of ") + allowed + ", got " + describe(*v));
        field = *parsed;
    };
    read_choice("triangle_test", s.accuracy.triangles, parse_triangle_test, "\"moller_trumbore\", \"watertight\"");
    read_choice("sphere_test", s.accuracy.spheres, parse_sphere_test, "\"quadratic\", \"cancellation_free\"");
    read_choice("fresnel", s.accuracy.fresnel, parse_fresnel_model, "\"schlick\", \"exact\"");
    read_choice("sampler", s.estimator.sampler, parse_sampler, "\"independent\", \"stratified\", \"sobol\"");
    read_choice("light_sampling", s.estimator.light_sampling, parse_light_sampling, "\"nee\", \"mis\"");
    read_choice("caustics", s.estimator.caustics, parse_caustic_paths,
                "\"path\", \"light_tracing\", \"photons\"");
    if (const Json* ratio = in.optional(j, "light_paths_per_pixel")) {
        const std::string ratio_path = member_path(path, "light_paths_per_pixel");
        s.estimator.light_paths_per_pixel = in.number(*ratio, ratio_path);
        if (!(s.estimator.light_paths_per_pixel >= 1.0f / 1024 && s.estimator.light_paths_per_pixel <= 64.0f))
            in.fail(ratio_path, "must be from 1/1024 to 64, got " + describe(*ratio));
    }
    if (const Json* radius = in.optional(j, "photon_radius")) {
        const std::string radius_path = member_path(path, "photon_radius");
        s.estimator.photon_radius = in.number(*radius, radius_path);
        if (!(s.estimator.photon_radius > 0.0f && s.estimator.photon_radius <= kPhotonRadiusMax))
            in.fail(radius_path, "must be greater than 0 and at most 1e18 (leave it out for the automatic radius), got " +
                                     describe(*radius));
    }
    if (const Json* clamp = in.optional(j, "clamp_indirect")) {
        const std::string clamp_path = member_path(path, "clamp_indirect");
        s.estimator.clamp_indirect = in.number(*clamp, clamp_path);
        if (!(s.estimator.clamp_indirect >= 0.0f))
            in.fail(clamp_path, "must be non-negative (0 turns the clamp off), got " + describe(*clamp));
    }
    if (const Json* threshold = in.optional(j, "adaptive_threshold")) {
        const std::string threshold_path = member_path(path, "adaptive_threshold");
        s.adaptive.threshold = in.number(*threshold, threshold_path);
        if (!(s.adaptive.threshold >= 0.0f))
            in.fail(threshold_path, "must be non-negative (0 turns adaptive sampling off), got " + describe(*threshold));
    }
    return s;
}

}  // namespace wt
