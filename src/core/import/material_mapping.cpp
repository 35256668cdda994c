#include "core/import/material_mapping.h"

#include <glm/common.hpp>

namespace wt {

glm::vec3 reflectance_from_file(const glm::vec3& c, const std::string& what, ImportedMaterial& out) {
    const glm::vec3 clamped = glm::clamp(c, glm::vec3(0.0f), glm::vec3(1.0f));
    if (clamped != c) out.unmapped.push_back(what + " outside [0, 1] (clamped)");
    return clamped;
}

void emission_from_file(const glm::vec3& e, const std::string& what, ImportedMaterial& out) {
    const glm::vec3 emission = glm::max(e, glm::vec3(0.0f));
    if (emission == glm::vec3(0.0f)) return;
    if (out.material.is_specular()) {
        out.unmapped.push_back(what + " on a mirror or glass");
        return;
    }
    out.material.emission = emission;
}

}  // namespace wt
