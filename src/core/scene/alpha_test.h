#pragma once
// glTF 2.0's alpha modes (3.9.4, alphaMode and alphaCutoff) as a test of one candidate hit,
// which the traversal asks before it records the hit (kernels/accel/alpha_filter.h), for every
// ray: camera, bounce, shadow, light and photon paths.

#include <cstdint>

namespace wt {

struct Scene;

// True if the hit on scene primitive `prim` at barycentrics (u, v) counts. alpha is the
// material's alpha_factor times its alpha texture's alpha at the hit's coordinates (the set
// that texture reads), read at level 0 (bilinear), whichever ray asks, so a camera ray and a
// shadow ray see the same cut-out. OPAQUE: always (glTF: alpha is ignored). MASK: alpha >= alpha_cutoff. BLEND: with
// probability alpha, by a coin drawn from hash(ray_key, prim) (stochastic transparency, as
// pbrt-v4's alpha textures between 0 and 1): the same ray meeting the same triangle always
// decides alike, so the decision depends on nothing but the ray. An instanced triangle reads
// its mesh's material and object-space coordinates; spheres always count. `context` is the
// Scene, as the kernels' BvhView carries it.
bool alpha_keeps_hit(const void* context, uint32_t prim, float u, float v, uint64_t ray_key);

// The uniform number in [0, 1) a BLEND hit is decided by: kept if it is below alpha.
float blend_coin(uint64_t ray_key, uint32_t prim);

}  // namespace wt
