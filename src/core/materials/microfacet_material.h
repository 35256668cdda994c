#pragma once
// Which material a scene file's rough "conductor" or "rough_glass" loads as. Roughness exactly 0
// is the smooth material, sampled by today's specular code: a smooth conductor is the mirror's
// reflection with the conductor's Fresnel weight (with F0 = 1 the mirror itself, bit for bit),
// and a smooth rough_glass is the glass, bit for bit. Below kMinGgxAlpha the rough lobe is
// clamped rather than made specular, so roughness 0.01 is a very sharp lobe, not a mirror.
// An index-matched glass (ior 1) bends and reflects nothing whatever its microfacets, and its
// rough form would have a refraction lobe that is a delta (Walter's Jacobian divides by zero):
// it loads as the smooth glass, which passes light straight through with weight 1.
//
// glTF's metallic-roughness material (principled.h) with metallic 1 is the specification's
// metal_brdf alone, which is the conductor with F0 = baseColor: it loads as that (the smooth
// conductor at roughness 0, so a white one is the mirror bit for bit), unless it emits, which
// only the diffuse and principled materials do. Any other metallic keeps both lobes, and at
// roughness 0 the specular lobe is the sharpest rough one (kMinGgxAlpha), not a delta: a
// delta beside a diffuse lobe would make the vertex both specular and not.

#include "core/description/scene_description.h"

namespace wt {

inline MaterialType conductor_type(float roughness) {
    return roughness > 0.0f ? MaterialType::rough_conductor : MaterialType::conductor;
}

inline MaterialType dielectric_type(float roughness, float ior) {
    return roughness > 0.0f && ior != 1.0f ? MaterialType::rough_glass : MaterialType::glass;
}

// The factors in range (the loaders check or clamp them); the name is left to the caller.
// metallic_varies: a texture will multiply metallic (glTF's metallicRoughnessTexture, MTL's
// map_Pm), so metallic 1 stays principled instead of loading as the conductor it otherwise is.
inline Material principled_material(const glm::vec3& base_color, float metallic, float roughness, float ior,
                                    const glm::vec3& emission, bool metallic_varies = false) {
    Material m;
    m.roughness = roughness;
    m.emission = emission;
    if (metallic == 1.0f && !m.is_emissive() && !metallic_varies) {
        m.type = conductor_type(roughness);
        m.f0 = base_color;
        return m;
    }
    m.type = MaterialType::principled;
    m.base_color = base_color;
    m.metallic = metallic;
    m.ior = ior;
    return m;
}

}  // namespace wt
