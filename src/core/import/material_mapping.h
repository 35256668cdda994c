#pragma once
// The steps every format's material mapping shares: our materials accept less than the files
// say (reflectances in [0, 1], emission only on diffuse surfaces), and what is dropped is named.

#include <string>

#include <glm/vec3.hpp>

#include "core/import/imported_mesh.h"

namespace wt {

// c clamped to [0, 1]; records `what` as not mapped if that changed it.
glm::vec3 reflectance_from_file(const glm::vec3& c, const std::string& what, ImportedMaterial& out);

// Sets the emission of a diffuse material (negative components to 0); on a mirror or glass,
// which cannot emit, records it as not mapped.
void emission_from_file(const glm::vec3& e, const std::string& what, ImportedMaterial& out);

}  // namespace wt
