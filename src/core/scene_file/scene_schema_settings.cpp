#include <cmath>
#include <cstdint>

#include <glm/geometric.hpp>

#include "core/camera/camera.h"
#include "core/scene_file/scene_schema.h"

// The camera and render sections.

namespace wt {

namespace {

// A finite number from the camera section, checked by `ok`, or the field named with `rule`.
template <typename Ok>
float camera_number(const Reader& in, const Json& j, const std::string& path, const char* key, Ok ok, const char* rule) {
    const std::string key_path = member_path(path, key);
    const float v = in.number(j, key_path);
    if (!(std::isfinite(v) && ok(v))) in.fail(key_path, std::string("must be ") + rule + ", got " + describe(j));
    return v;
}

// "projection", and what each one reads: the orthographic window's width, or the thin lens.
void read_projection(const Reader& in, const Json& j, const std::string& path, CameraDescription& camera) {
    if (const Json* projection = in.optional(j, "projection")) {
        const std::string projection_path = member_path(path, "projection");
        const std::string name = in.text(*projection, projection_path);
        if (name == "orthographic") camera.projection = Projection::orthographic;
        else if (name != "perspective")
            in.fail(projection_path, "must be one of \"perspective\", \"orthographic\", got " + describe(*projection));
    }
    if (camera.projection == Projection::orthographic) {
        for (const char* key : {"fov_degrees", "aperture_radius", "focus_distance", "focus_on"})
            if (in.optional(j, key))
                in.fail(member_path(path, key), "is for the perspective camera; an orthographic one takes width_world");
        const Json& width = in.required(j, "width_world", path);
        camera.width_world = camera_number(in, width, path, "width_world", [](float v) { return v > 0.0f; },
                                           "a positive number of scene units");
        return;
    }
    if (in.optional(j, "width_world"))
        in.fail(member_path(path, "width_world"), "is for \"projection\": \"orthographic\" only");
    read_thin_lens(in, j, path, camera);
}

}  // namespace

void read_thin_lens(const Reader& in, const Json& j, const std::string& path, CameraDescription& camera) {
    const auto positive = [](float v) { return v > 0.0f; };
    if (const Json* aperture = in.optional(j, "aperture_radius"))
        camera.aperture_radius = camera_number(in, *aperture, path, "aperture_radius", [](float v) { return v >= 0.0f; },
                                               "non-negative (0 is the pinhole)");
    const Json* distance = in.optional(j, "focus_distance");
    const Json* point = in.optional(j, "focus_on");
    if (distance && point) in.fail(member_path(path, "focus_on"), "cannot be given with focus_distance; give one");
    if (distance)
        camera.focus_distance = camera_number(in, *distance, path, "focus_distance", positive,
                                              "greater than 0 (the distance along the view axis to the sharp plane)");
    if (point) {
        const std::string point_path = member_path(path, "focus_on");
        const glm::vec3 p = in.vec3(*point, point_path);
        // The plane of focus goes through the point, square to the view axis.
        const glm::dvec3 forward = glm::normalize(glm::dvec3(camera.look_at) - glm::dvec3(camera.eye));
        const double depth = glm::dot(glm::dvec3(p) - glm::dvec3(camera.eye), forward);
        if (!(float(depth) > 0.0f && std::isfinite(float(depth))))
            in.fail(point_path, "must lie in front of the eye (its depth along the view axis is " + std::to_string(depth) +
                                    "), got " + format_vec3(p));
        camera.focus_distance = float(depth);
    }
}

CameraDescription read_camera(const Reader& in, const Json& j, const std::string& path, const RenderSettings& render,
                              std::vector<std::string>& notes) {
    in.expect_object(j, path);
    if (in.optional(j, "gltf")) return read_gltf_camera_section(in, j, path, render, notes);
    in.check_keys(j, path, {"eye", "look_at", "up", "fov_degrees", "projection", "width_world", "aperture_radius",
                            "focus_distance", "focus_on"});
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
    const glm::vec3 difference = camera.look_at - camera.eye;
    if (!std::isfinite(difference.x) || !std::isfinite(difference.y) || !std::isfinite(difference.z))
        in.fail(member_path(path, "look_at"), "look_at - eye overflows a 32-bit float (eye " + format_vec3(camera.eye) +
                                                  ", look_at " + format_vec3(camera.look_at) + ")");
    const CameraBasis basis = camera_basis(camera);
    if (!is_unit_in_float(basis.forward))
        in.fail(member_path(path, "look_at"), "look_at - eye = " + format_vec3(difference) +
                                                  " cannot be normalised in 32-bit float (too short or too long)");
    if (!is_unit_in_float(basis.right) || !is_unit_in_float(basis.up))
        in.fail(member_path(path, "up"), "cannot be used in 32-bit float: cross(forward, up) cannot be normalised "
                                         "(up too short or too long), got " + format_vec3(camera.up));
    read_projection(in, j, path, camera);
    return camera;
}

RenderSettings read_render(const Reader& in, const Json& j, const std::string& path) {
    in.expect_object(j, path);
    in.check_keys(j, path, {"width", "height", "spp", "shadow_rays", "seed", "max_bounces", "rr_start_bounce",
                            "triangle_test", "sphere_test", "fresnel", "multiple_scattering", "sampler", "light_sampling", "light_selection", "clamp_indirect",
                            "caustics", "light_paths_per_pixel", "photon_radius", "adaptive_threshold",
                            "adaptive_min_spp", "filter", "filter_width"});
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
    read_choice("multiple_scattering", s.accuracy.multiple_scattering, parse_multiple_scattering, "\"none\", \"kulla_conty\"");
    read_choice("sampler", s.estimator.sampler, parse_sampler, "\"independent\", \"stratified\", \"sobol\"");
    read_choice("light_sampling", s.estimator.light_sampling, parse_light_sampling, "\"nee\", \"mis\"");
    read_choice("light_selection", s.estimator.light_selection, parse_light_selection, "\"auto\", \"area\", \"power\", \"bvh\"");
    read_choice("caustics", s.estimator.caustics, parse_caustic_paths,
                "\"path\", \"light_tracing\", \"photons\"");
    read_choice("filter", s.filter.kind, parse_filter_kind, "\"box\", \"gaussian\", \"blackman_harris\", \"mitchell\"");
    s.filter.width = default_filter_width(s.filter.kind);
    if (const Json* width = in.optional(j, "filter_width")) {
        const std::string width_path = member_path(path, "filter_width");
        s.filter.width = in.number(*width, width_path);
        if (!(s.filter.width > 0.0f && s.filter.width <= kMaxFilterWidth))
            in.fail(width_path, "must be greater than 0 and at most 16 pixels, got " + describe(*width));
    }
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
