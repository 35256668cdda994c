#pragma once
// Which material a scene file's rough "conductor" or "rough_glass" loads as. Roughness exactly 0
// is the smooth material, sampled by today's specular code: a smooth conductor is the mirror's
// reflection with the conductor's Fresnel weight (with F0 = 1 the mirror itself, bit for bit),
// and a smooth rough_glass is the glass, bit for bit. Below kMinGgxAlpha the rough lobe is
// clamped rather than made specular, so roughness 0.01 is a very sharp lobe, not a mirror.
// An index-matched glass (ior 1) bends and reflects nothing whatever its microfacets, and its
// rough form would have a refraction lobe that is a delta (Walter's Jacobian divides by zero):
// it loads as the smooth glass, which passes light straight through with weight 1.

#include "core/scene_description.h"

namespace wt {

inline MaterialType conductor_type(float roughness) {
    return roughness > 0.0f ? MaterialType::rough_conductor : MaterialType::conductor;
}

inline MaterialType dielectric_type(float roughness, float ior) {
    return roughness > 0.0f && ior != 1.0f ? MaterialType::rough_glass : MaterialType::glass;
}

}  // namespace wt
