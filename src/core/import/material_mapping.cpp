#include "core/import/material_mapping.h"

#include <glm/common.hpp>

namespace wt {

glm::vec3 reflectance_from_file(const glm::vec3& c, const std::string& what, ImportedMaterial& out) {
    const glm::vec3 clamped = glm::clamp(c, glm::vec3(0.0f), glm::vec3(1.0f));
    if (clamped != c) out.unmapped.push_back(what + " outside [0, 1] (clamped)");
    return clamped;
}

float fraction_from_file(double v, const std::string& what, ImportedMaterial& out) {
    const double clamped = v >= 0.0 ? (v <= 1.0 ? v : 1.0) : 0.0;  // NaN fails both tests: 0
    if (!(clamped == v)) out.unmapped.push_back(what + " outside [0, 1] (clamped)");
    return float(clamped);
}

void emission_from_file(const glm::vec3& e, const std::string& what, ImportedMaterial& out) {
    const glm::vec3 emission = glm::max(e, glm::vec3(0.0f));
    if (emission == glm::vec3(0.0f)) return;
    const Material& m = out.material;
    if (m.is_specular() || (m.is_microfacet() && m.type != MaterialType::principled)) {
        out.unmapped.push_back(what + " on a mirror, metal or glass");
        return;
    }
    out.material.emission = emission;
}

}  // namespace wt
