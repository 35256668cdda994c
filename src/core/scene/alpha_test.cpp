#include "core/scene/alpha_test.h"

#include <cmath>

#include "core/sampling/rng.h"
#include "core/scene/scene.h"
#include "core/textures/texture_lookup.h"

namespace wt {

float blend_coin(uint64_t ray_key, uint32_t prim) {
    // splitmix64's mixer (core/sampling/rng.h) of the key and the primitive, its top 24 bits
    // as a float in [0, 1): exact, so the comparison with alpha is the same everywhere.
    const uint64_t h = mix64(ray_key ^ mix64(uint64_t(prim) + 0x9E3779B97F4A7C15ull));
    return float(h >> 40) * 0x1p-24f;
}

bool alpha_keeps_hit(const void* context, uint32_t prim, float u, float v, uint64_t ray_key) {
    const Scene& scene = *static_cast<const Scene*>(context);
    // The triangle's material and coordinates: the scene's own, or its instanced mesh's (the
    // traversal names an instanced triangle by its id in the scene, as the shade stage does).
    const TriangleSoA* triangles = &scene.triangles;
    const TextureCoordinateTable* coordinates = &scene.texture_coordinates;
    uint32_t row = prim;
    if (prim >= scene.triangles.size()) {
        if (scene.instances.empty() || prim < scene.instances.first_id) return true;  // a sphere
        const Instance& k = scene.instances.instance_of(prim);
        const InstancedMesh& mesh = scene.instances.meshes[k.mesh];
        triangles = &mesh.triangles, coordinates = &mesh.texture_coordinates, row = prim - k.first_id;
    }
    const Material& m = scene.materials[triangles->material[row]];
    if (!m.is_alpha_tested()) return true;
    float alpha = m.alpha_factor;
    if (m.alpha_texture >= 0 && row < coordinates->size()) {
        const MipPyramid& t = scene.textures[std::size_t(m.alpha_texture)];
        alpha *= texture_lookup(t, t.transformed(coordinates->at(*triangles, row, u, v, t.coordinate_set())), -INFINITY).w;
    }
    if (m.alpha_mode == AlphaMode::mask) return !(alpha < m.alpha_cutoff);
    return blend_coin(ray_key, prim) < alpha;
}

}  // namespace wt
