#include "core/import/gltf_lights.h"

#include <cmath>

#include <glm/geometric.hpp>

namespace wt {

namespace {

constexpr double kLumensPerWatt = 683.0;
constexpr double kPiDouble = 3.14159265358979323846;

}  // namespace

int gltf_node_light(const tinygltf::Node& node) {
    const auto ext = node.extensions.find("KHR_lights_punctual");
    if (ext == node.extensions.end() || !ext->second.IsObject() || !ext->second.Has("light")) return -1;
    const tinygltf::Value& light = ext->second.Get("light");
    return light.IsInt() ? light.GetNumberAsInt() : -2;  // -2: named, but not as an index
}

void read_gltf_light(const std::string& path, const tinygltf::Model& model, int index, const glm::dmat4& world,
                     ImportedMesh& mesh) {
    const std::string where = path + ": KHR_lights_punctual light " + std::to_string(index);
    const auto fail = [&](const std::string& what) { throw MeshFileError(where + ": " + what); };
    if (index < 0 || std::size_t(index) >= model.lights.size()) fail("does not exist");
    const tinygltf::Light& l = model.lights[std::size_t(index)];
    glm::dvec3 color(1.0);
    if (!l.color.empty()) {
        if (l.color.size() != 3) fail("color has " + std::to_string(l.color.size()) + " components, not 3");
        color = glm::dvec3(l.color[0], l.color[1], l.color[2]);
    }
    for (int c = 0; c < 3; ++c)
        if (!(std::isfinite(color[c]) && color[c] >= 0.0)) fail("color components must be finite and >= 0");
    if (!(std::isfinite(l.intensity) && l.intensity >= 0.0)) fail("intensity must be finite and >= 0");
    if (l.range > 0.0)
        mesh.notes.push_back("KHR_lights_punctual light " + std::to_string(index) +
                             ": range is ignored (light falls off with the inverse square alone, as physics has it)");
    // Per 683 lm/W: W/sr from candela, W/m² from lux.
    const glm::dvec3 radiometric = color * (l.intensity / kLumensPerWatt);
    if (!(radiometric.x > 0.0 || radiometric.y > 0.0 || radiometric.z > 0.0)) {
        mesh.notes.push_back("KHR_lights_punctual light " + std::to_string(index) + ": emits nothing, left out");
        return;
    }
    LightDescription d;
    d.position = glm::vec3(world * glm::dvec4(0.0, 0.0, 0.0, 1.0));
    const glm::dvec3 axis(world * glm::dvec4(0.0, 0.0, -1.0, 0.0));
    const double axis_length = glm::length(axis);
    if (l.type == "point") {
        d.type = LightType::point;
        d.intensity = glm::vec3(radiometric);
    } else if (l.type == "spot" || l.type == "directional") {
        if (!(axis_length > 0.0 && std::isfinite(axis_length))) fail("its node's transform leaves it no direction");
        d.direction = glm::vec3(axis / axis_length);
        if (l.type == "directional") {
            d.type = LightType::directional;
            d.irradiance = glm::vec3(radiometric);
        } else {
            const double inner = l.spot.innerConeAngle, outer = l.spot.outerConeAngle;
            if (!(inner >= 0.0 && inner < outer && outer <= 0.5 * kPiDouble))
                fail("spot cone angles must have 0 <= innerConeAngle < outerConeAngle <= pi/2, got " +
                     std::to_string(inner) + " and " + std::to_string(outer));
            d.type = LightType::spot;
            d.intensity = glm::vec3(radiometric);
            d.cone_degrees = float(2.0 * outer * 180.0 / kPiDouble);
            d.blend = float(1.0 - inner / outer);
        }
    } else {
        fail("type \"" + l.type + "\" is not point, spot or directional");
    }
    for (float p : {d.position.x, d.position.y, d.position.z})
        if (!std::isfinite(p)) fail("its node's transform puts it at a non-finite position");
    mesh.lights.push_back(d);
}

}  // namespace wt
