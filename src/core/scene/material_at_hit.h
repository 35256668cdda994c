#pragma once
// The material at a hit: the scene's own, or, for a material with textures, a copy whose
// textured parameters (albedo or base colour, ...) are looked up at the hit's texture
// coordinates. Every vertex of a path (camera or light, either integrator) asks here, so the
// reference and the wavefront kernels shade a textured surface alike.

#include <optional>

#include "core/scene/scene.h"

namespace wt {

// Fills `textured` (a copy of the hit's material) with its texture lookups, and a normal map's
// shading normal into `surface` (smooth where it differs from the geometric one). from_camera: the hit
// is a camera ray's, whose ray cone picks the texture level; every other ray reads level 0 (README,
// "Textures", says why). Out of line: only textured materials call it.
void apply_textures(const Scene& scene, const Hit& hit, SurfacePoint& surface, const Ray& ray, bool from_camera,
                    Material& textured);

// `scratch` outlives the returned reference's use. Optional, so that an untextured scene's
// loops construct no Material; reused across a loop's hits, the copy's name does not allocate.
inline const Material& material_at(const Scene& scene, const Hit& hit, SurfacePoint& surface, const Ray& ray,
                                   bool from_camera, std::optional<Material>& scratch) {
    const Material& m = scene.materials[surface.material];
    if (!m.has_textures()) return m;
    if (scratch) *scratch = m;
    else scratch.emplace(m);
    apply_textures(scene, hit, surface, ray, from_camera, *scratch);
    return *scratch;
}

}  // namespace wt
