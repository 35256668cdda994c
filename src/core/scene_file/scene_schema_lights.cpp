#include <cmath>
#include <memory>

#include <glm/geometric.hpp>

#include "core/image_io/rgb_image_input.h"
#include "core/scene_file/scene_schema.h"

// The "lights" section: the environment and the punctual lights (README, "Lights").

namespace wt {
namespace {

constexpr const char* kLightTypes = "environment, point, spot, directional";

LightType read_light_type(const Reader& in, const Json& j, const std::string& path) {
    const std::string type = in.text(j, path);
    if (type == "environment") return LightType::environment;
    if (type == "point") return LightType::point;
    if (type == "spot") return LightType::spot;
    if (type == "directional") return LightType::directional;
    in.fail(path, std::string("unknown light type (allowed: ") + kLightTypes + "), got " + describe(j));
}

// A light's colour (radiance, intensity, irradiance): non-negative, and not all zero, which
// would be a light that does nothing (most likely a slip).
glm::vec3 read_emitted(const Reader& in, const Json& j, const char* key, const std::string& path) {
    const std::string field = member_path(path, key);
    const glm::vec3 c = in.color(in.required(j, key, path), field, false);
    if (!(c.x > 0.0f || c.y > 0.0f || c.z > 0.0f)) in.fail(field, "a light must emit something, got [0, 0, 0]");
    return c;
}

glm::vec3 read_direction(const Reader& in, const Json& j, const std::string& path) {
    const std::string field = member_path(path, "direction");
    const glm::vec3 d = in.vec3(in.required(j, "direction", path), field);
    const float length = glm::length(d);
    if (!(length > 0.0f) || !std::isfinite(length)) in.fail(field, "must be a non-zero vector, got " + describe(j["direction"]));
    return d / length;
}

float read_number_in(const Reader& in, const Json& j, const char* key, const std::string& path, float fallback, float lo,
                     float hi, bool lo_open, const char* range) {
    const Json* v = in.optional(j, key);
    if (!v) return fallback;
    const std::string field = member_path(path, key);
    const float x = in.number(*v, field);
    if (!((lo_open ? x > lo : x >= lo) && x <= hi)) in.fail(field, std::string("must be in ") + range + ", got " + describe(*v));
    return x;
}

// The map's texels, which must all be finite and non-negative radiance: a NaN or negative texel
// would be light the sampling could not weigh, and is refused (not clamped), naming the pixel.
std::shared_ptr<const EnvironmentMap> read_environment_map(const Reader& in, const std::string& file,
                                                           const std::string& field) {
    const std::string resolved = in.resolve(file);
    RgbImage image;
    try {
        image = read_rgb_image(resolved);
    } catch (const ImageError& e) {
        in.fail(field, std::string("cannot use the environment map: ") + e.what());
    }
    if (image.width < 1 || image.height < 1) in.fail(field, "the environment map " + resolved + " has no pixels");
    for (std::size_t i = 0; i < image.rgb.size(); ++i)
        if (!(image.rgb[i] >= 0.0f) || !std::isfinite(image.rgb[i])) {
            const std::size_t pixel = i / 3;
            in.fail(field, "the environment map " + resolved + " has a negative or non-finite texel at (" +
                               std::to_string(pixel % std::size_t(image.width)) + ", " +
                               std::to_string(pixel / std::size_t(image.width)) + "): " + format_double(image.rgb[i]) +
                               " (radiance must be finite and non-negative)");
        }
    auto map = std::make_shared<EnvironmentMap>();
    map->width = image.width;
    map->height = image.height;
    map->rgb = std::move(image.rgb);
    return map;
}

LightDescription read_light(const Reader& in, const Json& j, const std::string& path) {
    in.expect_object(j, path);
    LightDescription l;
    l.type = read_light_type(in, in.required(j, "type", path), member_path(path, "type"));
    switch (l.type) {
        case LightType::environment:
            in.check_keys(j, path, {"type", "radiance", "file", "strength", "rotate_degrees"}, " for an environment");
            if (const Json* file = in.optional(j, "file")) {
                if (in.optional(j, "radiance"))
                    in.fail(member_path(path, "radiance"), "give either radiance or a map file, not both");
                const std::string field = member_path(path, "file");
                l.file = in.text(*file, field);
                if (l.file.empty()) in.fail(field, "must not be empty");
                l.strength = read_number_in(in, j, "strength", path, 1.0f, 0.0f, 3.4e38f, true, "(0, inf)");
                l.rotate_degrees = read_number_in(in, j, "rotate_degrees", path, 0.0f, -360.0f, 360.0f, false, "[-360, 360]");
                l.map = read_environment_map(in, l.file, field);
            } else {
                if (in.optional(j, "strength") || in.optional(j, "rotate_degrees"))
                    in.fail(member_path(path, in.optional(j, "strength") ? "strength" : "rotate_degrees"),
                            "applies to a map file only");
                l.radiance = read_emitted(in, j, "radiance", path);
            }
            break;
        case LightType::point:
            in.check_keys(j, path, {"type", "position", "intensity"}, " for a point light");
            l.position = in.vec3(in.required(j, "position", path), member_path(path, "position"));
            l.intensity = read_emitted(in, j, "intensity", path);
            break;
        case LightType::spot:
            in.check_keys(j, path, {"type", "position", "direction", "intensity", "cone_degrees", "blend"}, " for a spot light");
            l.position = in.vec3(in.required(j, "position", path), member_path(path, "position"));
            l.direction = read_direction(in, j, path);
            l.intensity = read_emitted(in, j, "intensity", path);
            in.required(j, "cone_degrees", path);
            l.cone_degrees = read_number_in(in, j, "cone_degrees", path, 0.0f, 0.0f, 180.0f, true, "(0, 180]");
            l.blend = read_number_in(in, j, "blend", path, 0.0f, 0.0f, 1.0f, false, "[0, 1]");
            break;
        case LightType::directional:
            in.check_keys(j, path, {"type", "direction", "irradiance", "angle_degrees"}, " for a directional light");
            l.direction = read_direction(in, j, path);
            l.irradiance = read_emitted(in, j, "irradiance", path);
            // Up to a hemisphere's worth: a wider "sun" would light surfaces from behind their horizon alike.
            l.angle_degrees = read_number_in(in, j, "angle_degrees", path, 0.0f, 0.0f, 180.0f, false, "[0, 180]");
            break;
    }
    return l;
}

}  // namespace

std::vector<LightDescription> read_lights(const Reader& in, const Json& j, const std::string& path) {
    in.expect_array(j, path);
    std::vector<LightDescription> lights;
    bool environment = false;
    for (std::size_t i = 0; i < j.size(); ++i) {
        const std::string element = element_path(path, i);
        lights.push_back(read_light(in, j[i], element));
        if (lights.back().type != LightType::environment) continue;
        if (environment) in.fail(element, "a scene has at most one environment, and an earlier light is one");
        environment = true;
    }
    return lights;
}

}  // namespace wt
