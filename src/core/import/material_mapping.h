#pragma once
// The steps every format's material mapping shares: our materials accept less than the files
// say (reflectances and factors in [0, 1], emission only on diffuse and principled surfaces), and what is dropped is named.

#include <string>

#include <glm/vec3.hpp>

#include "core/import/imported_mesh.h"

namespace wt {

// c clamped to [0, 1]; records `what` as not mapped if that changed it.
glm::vec3 reflectance_from_file(const glm::vec3& c, const std::string& what, ImportedMaterial& out);

// v clamped to [0, 1] (NaN to 0); records `what` as not mapped if that changed it.
float fraction_from_file(double v, const std::string& what, ImportedMaterial& out);

// Sets the emission of a diffuse or principled material (negative components to 0); on a
// mirror, metal or glass, which cannot emit, records it as not mapped.
void emission_from_file(const glm::vec3& e, const std::string& what, ImportedMaterial& out);

}  // namespace wt
