#pragma once
// Meshes stored once and placed many times: each instance is a transform (object -> world, and
// its inverse, both rounded to float once from the double matrix) and a mesh. The triangles of
// instance k take the ids [first_id, first_id + its mesh's size) after the scene's own triangles
// and spheres, so a hit still names one primitive with one 32-bit id, and the same id a scene
// flattened in instance order would give it (offset by the sphere count).
//
// A scene without instances stores nothing here, and surface_at() never comes here.

#include <cstdint>
#include <vector>

#include "core/geometry/geometry_soa.h"
#include "core/instances/affine_transform.h"
#include "core/geometry/shading_normals.h"
#include "core/geometry/texture_coordinates.h"

namespace wt {

struct InstancedMesh {
    TriangleSoA triangles;               // object space; triangles only (no parallelograms)
    ShadingNormalTable shading_normals;  // empty unless the mesh has vertex normals
    TextureCoordinateTable texture_coordinates;  // object space; empty unless the scene has textures
};

struct Instance {
    AffineTransform to_world, to_object;
    uint32_t mesh = 0;
    uint32_t first_id = 0;  // id of its mesh's triangle 0
};

struct SceneInstances {
    std::vector<InstancedMesh> meshes;
    std::vector<Instance> instances;  // in id order
    uint32_t first_id = 0;            // id of the first instanced triangle
    uint64_t triangle_count = 0;      // of all instances together

    bool empty() const { return instances.empty(); }
    // The instance whose ids hold `prim` (>= first_id, < first_id + triangle_count).
    const Instance& instance_of(uint32_t prim) const;
};

// Ids a hit can name: the kernels break ties between equal distances by the smaller id,
// compared as int32, so ids stay below 2^31.
constexpr uint64_t kMaxPrimitiveIds = 0x7FFFFFFFull;

}  // namespace wt
