#pragma once
// The scene as the renderer sees it: SoA geometry, materials, the light table and the camera.
// Only what the description contains is built; an empty sphere buffer means the intersect
// stage runs no sphere code at all.

#include <cstdint>
#include <vector>

#include <glm/geometric.hpp>

#include "core/camera/camera.h"
#include "core/camera/pixel_filter.h"
#include "core/geometry/geometry_soa.h"
#include "core/instances/scene_instances.h"
#include "core/lights/emitter_selection.h"
#include "core/lights/light_table.h"
#include "core/lights/scene_lights.h"
#include "core/base/ray.h"
#include "core/base/ray_offset.h"
#include "core/description/scene_description.h"
#include "core/geometry/shading_normals.h"
#include "core/textures/mip_pyramid.h"
#include "core/geometry/texture_coordinates.h"

namespace wt {

struct Scene {
    RenderSettings settings;
    Camera camera;
    PixelFilter pixel_filter;  // where in and about its pixel each camera sample lands
    std::vector<Material> materials;
    TriangleSoA triangles;
    ShadingNormalTable shading_normals;  // empty unless some mesh has vertex normals
    SphereSoA spheres;
    // Meshes stored once and placed by instances, their ids after the spheres'; empty unless the
    // description has instances, and then the renderer traces the flat BVH alone.
    SceneInstances instances;
    LightTable lights;  // the emissive triangles
    // Their selection by power or by the light tree (render.light_selection), where there are two
    // or more of them; empty with "area" (LightTable's own choice).
    EmitterSelection emitter_selection;
    // The scene file's "lights" list, with the area lights as one entry of its selection; empty
    // without the list and without an emitter selection, and then no code reads it (the
    // integrators pick their loop once). With an emitter selection alone it holds the area
    // lights only, and the integrators run the listed lights' samplers, which ask the selection.
    SceneLights listed_lights;
    // Light paths estimate the caustics seen directly (path_vertex.h, light_paths_count_emission):
    // asked for by the settings, and the scene has lights and a mirror or glass surface.
    bool light_traces_caustics = false;
    // And the camera paths whose first hit is a mirror or glass gather the same light paths as
    // photons (path_vertex.h, kernels/photons): asked for, light-traced, and some diffuse
    // surface reflects light.
    bool merges_photons = false;
    // Some material is rough (rough conductor or glass, principled): the vertex loop is compiled
    // with the rough materials' light samples and pdfs only where this is set, so the other
    // scenes run the loop they ran before rough materials existed (kernels/wavefront/shade_queue.h).
    bool has_rough_materials = false;
    // Some material is alpha-tested (glTF alphaMode MASK or BLEND): the traversal asks
    // core/scene/alpha_test.h about every candidate hit, through the BVH (kernels/accel/
    // alpha_filter.h). Without it the kernels never ask.
    bool has_alpha_materials = false;
    // Image textures, indexed by Material::color_texture and the like, and the coordinates they
    // are looked up at; both empty unless some material has a texture. A textured scene shades
    // with the loop that tests materials at run time (kernels/wavefront/stage_shade.cpp), and
    // looks its materials up through core/scene/material_at_hit.h.
    std::vector<MipPyramid> textures;
    TextureCoordinateTable texture_coordinates;
    // The camera's ray cone (Akenine-Moller et al. 2019): its width at distance t is
    // cone_width0 + cone_spread * t, which picks the texture level a camera ray's hit reads.
    float cone_width0 = 0.0f, cone_spread = 0.0f;

    bool has_textures() const { return !textures.empty(); }

    // The scene's own primitives, not the instances' (those are always traced through a BVH).
    uint32_t primitive_count() const { return uint32_t(triangles.size() + spheres.size()); }
};

// Validates nothing but what would read out of bounds (a mesh's normal count differing from
// its vertex count, std::invalid_argument): descriptions come from the loader (which
// validates) or from code. A mesh with vertex normals is never stored as a parallelogram.
Scene build_scene(const SceneDescription& description);

// Scene::light_traces_caustics, from the description alone (for the film's channels before the
// scene is built): the settings ask for light tracing (or photons, which trace the same light
// paths), some triangle emits and some surface is a mirror or glass.
bool light_traces_caustics(const SceneDescription& description);

// What the shade stage needs to know about a hit.
struct SurfacePoint {
    glm::vec3 position;
    glm::vec3 error;   // bound on the rounding error of position, for offset_ray_origin()
    // Geometric: winding for triangles, outward for spheres. It alone decides which side a ray
    // is on: ray offsets, emission's front face, glass inside/outside, what is below the surface.
    glm::vec3 normal;
    // What scattering is computed about: the interpolated vertex normal (unit, in the vertex
    // normals' orientation, which may be opposite to `normal`), or `normal` itself, the same
    // bits, on flat triangles and spheres.
    glm::vec3 shading_normal;
    uint32_t material;
    // shading_normal != normal, decided once here: the vertex code takes the flat path, the one
    // every scene without vertex normals runs, on a single flag test.
    bool smooth;
};

// A hit on an instanced triangle (hit.prim >= scene.instances.first_id): the point, its error
// bound and the normals in world space. Out of line, so the flat scenes' surface_at() stays as it was.
SurfacePoint instance_surface_at(const Scene& scene, const Hit& hit);

// Always inlined: g++'s choice to inline it into a shade loop hangs on the rest of the
// translation unit, and beside other instantiations of the loop (one per estimator, and the
// loops that record AOVs) it chose a call, which cost the loop several percent.
[[gnu::always_inline]] inline SurfacePoint surface_at(const Scene& scene, const Ray& ray, const Hit& hit) {
    SurfacePoint s;
    const uint32_t triangle_count = uint32_t(scene.triangles.size());
    if (hit.prim < triangle_count) {
        const TriangleSoA& t = scene.triangles;
        // From barycentrics rather than o + t*d: its error does not grow with the hit distance,
        // which is what the ulp-based ray offset assumes.
        const TriangleSoA::Corner c = t.corner(hit.prim);
        s.position = c.v0 + hit.u * c.e1 + hit.v * c.e2;
        s.error = triangle_point_error(c.v0, c.e1, c.e2, hit.u, hit.v);
        if (scene.settings.accuracy.triangles == TriangleTest::watertight) s.error = with_watertight_floor(s.error);
        s.normal = TriangleSoA::unit_normal(c.e1, c.e2);
        s.shading_normal = s.normal;
        s.smooth = false;
        if (!scene.shading_normals.empty()) {
            s.shading_normal = scene.shading_normals.at(t, hit.prim, hit.u, hit.v, s.normal);
            s.smooth = s.shading_normal != s.normal;
        }
        s.material = t.material[hit.prim];
    } else {
        const uint32_t i = hit.prim - triangle_count;
        if (i >= scene.spheres.size()) return instance_surface_at(scene, hit);
        const glm::vec3 c = scene.spheres.center(i);
        const float r = scene.spheres.radius[i];
        s.normal = glm::normalize(ray.origin + hit.t * ray.direction - c);
        s.shading_normal = s.normal;
        s.smooth = false;
        // Projected back onto the sphere, for the same reason.
        s.position = c + r * s.normal;
        s.error = sphere_point_error(c, r, s.normal);
        s.material = scene.spheres.material[i];
    }
    return s;
}

}  // namespace wt
