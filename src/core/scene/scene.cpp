#include "core/scene/scene.h"

#include "core/description/vertex_attribute_counts.h"
#include "core/geometry/mesh_texture_coordinates.h"
#include "core/instances/build_instances.h"
#include "core/materials/microfacet_bsdf.h"
#include "core/materials/multiple_scattering.h"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace wt {

bool light_traces_caustics(const SceneDescription& d) {
    if (d.settings.estimator.caustics == CausticPaths::path) return false;  // photons are light tracing's paths too
    // An orthographic camera's rays share one direction: no light path can be joined to it, so its
    // caustics are the camera paths' (the loader refuses asking for light tracing with it).
    if (d.camera.projection == Projection::orthographic) return false;
    const auto has = [&](bool (Material::*property)() const) {
        const auto used = [&](uint32_t material) { return (d.materials[material].*property)(); };
        const auto in_mesh = [&](const TriangleMesh& m) { return !m.triangles.empty() && used(m.material); };
        return std::any_of(d.meshes.begin(), d.meshes.end(), in_mesh) ||
               std::any_of(d.spheres.begin(), d.spheres.end(), [&](const Sphere& s) { return used(s.material); }) ||
               std::any_of(d.prototypes.begin(), d.prototypes.end(), [&](const MeshPrototype& p) {
                   return std::any_of(p.parts.begin(), p.parts.end(), in_mesh);
               });
    };
    // Area lights are triangles only: an emissive sphere is not sampled as a light. Light paths
    // start at the "lights" list's lights too.
    const bool has_triangle_light = std::any_of(d.meshes.begin(), d.meshes.end(), [&](const TriangleMesh& m) {
        return !m.triangles.empty() && d.materials[m.material].is_emissive();
    });
    return (has_triangle_light || !d.lights.empty()) && has(&Material::is_specular);
}

namespace {

// A sphere about the bounding box's centre that holds every primitive: what the lights at
// infinity's power is measured on and their light paths start from (core/lights/scene_lights.h).
// Radius 1 for an empty scene.
BoundingSphere bounding_sphere(const Scene& scene) {
    glm::vec3 lo(INFINITY), hi(-INFINITY);
    for (uint32_t i = 0; i < scene.triangles.size(); ++i) {
        const glm::vec3 v0 = scene.triangles.vertex0(i);
        for (const glm::vec3& v : {v0, v0 + scene.triangles.edge1(i), v0 + scene.triangles.edge2(i),
                                   v0 + scene.triangles.edge1(i) + scene.triangles.edge2(i)})
            lo = glm::min(lo, v), hi = glm::max(hi, v);
    }
    for (uint32_t i = 0; i < scene.spheres.size(); ++i) {
        const glm::vec3 c = scene.spheres.center(i);
        lo = glm::min(lo, c - scene.spheres.radius[i]), hi = glm::max(hi, c + scene.spheres.radius[i]);
    }
    // Each instance by its mesh's object box placed (corner by corner: the box of the box).
    std::vector<std::pair<glm::vec3, glm::vec3>> boxes(scene.instances.meshes.size(), {glm::vec3(INFINITY), glm::vec3(-INFINITY)});
    for (std::size_t m = 0; m < boxes.size(); ++m) {
        const TriangleSoA& t = scene.instances.meshes[m].triangles;
        for (std::size_t i = 0; i < t.size(); ++i)
            for (const glm::vec3& v : {t.vertex0(i), t.vertex1(i), t.vertex2(i)})
                boxes[m].first = glm::min(boxes[m].first, v), boxes[m].second = glm::max(boxes[m].second, v);
    }
    for (const Instance& k : scene.instances.instances) {
        const auto& [box_lo, box_hi] = boxes[k.mesh];
        for (int c = 0; c < 8; ++c) {
            const glm::vec3 p = k.to_world.point({(c & 1) ? box_hi.x : box_lo.x, (c & 2) ? box_hi.y : box_lo.y, (c & 4) ? box_hi.z : box_lo.z});
            lo = glm::min(lo, p), hi = glm::max(hi, p);
        }
    }
    if (!(lo.x <= hi.x)) return {glm::vec3(0.0f), 1.0f};  // nothing in the scene
    const float r = 0.5f * glm::length(hi - lo);
    return {0.5f * (lo + hi), r > 0.0f && std::isfinite(r) ? r : 1.0f};
}

// The ray cone of a camera ray (Akenine-Moller et al. 2019, section 20.3.4): a pinhole's spread
// is the angle one pixel subtends at the image's centre (a thin lens is taken as its pinhole);
// an orthographic camera's rays are parallel, each one pixel wide.
void set_camera_cone(Scene& scene, const SceneDescription& d) {
    const float height = float(d.settings.height);
    if (d.camera.projection == Projection::orthographic) {
        scene.cone_width0 = d.camera.width_world / float(d.settings.width);
        return;
    }
    scene.cone_spread = 2.0f * std::tan(0.5f * d.camera.fov_degrees * 3.14159265358979f / 180.0f) / height;
}

// Kulla & Conty's lobe (core/materials/multiple_scattering.h) for every GGX reflection lobe:
// the rough conductors' and the principled materials'. Rough glass keeps single scattering (its
// compensation needs tables per index of refraction and side; README, "Rough materials"). The
// albedo table is computed here, before rendering, rather than by the first vertex that needs it.
void add_multiple_scattering(std::vector<Material>& materials) {
    bool any = false;
    for (Material& m : materials) {
        if (m.type != MaterialType::rough_conductor && m.type != MaterialType::principled) continue;
        m.multiple_scattering = true;
        if (m.eta.x > 0.0f) m.conductor_fresnel_average = exact_fresnel_average(conductor_fresnel(m));
        any = true;
    }
    if (any) ggx_albedo_table();
}

}  // namespace

Scene build_scene(const SceneDescription& description) {
    Scene scene;
    scene.settings = description.settings;
    scene.camera = Camera(description.camera, description.settings.width, description.settings.height);
    scene.pixel_filter = PixelFilter(description.settings.filter);
    scene.materials = description.materials;
    if (description.settings.accuracy.multiple_scattering == MultipleScattering::kulla_conty)
        add_multiple_scattering(scene.materials);
    // Parallelograms first (TriangleSoA keeps them as a prefix), and only for the test that
    // knows them. A mesh with vertex normals stays triangles: there is no interpolating them
    // over a parallelogram.
    const bool parallelograms = description.settings.accuracy.triangles == TriangleTest::moller_trumbore;
    // Nor one with texture coordinates, which a hit interpolates by its triangle's barycentrics.
    auto as_parallelogram = [&](const TriangleMesh& m) {
        return parallelograms && m.parallelogram && m.normals.empty() && m.uvs.empty();
    };
    // The coordinate table exists only if some material will read it.
    const bool textured = std::any_of(description.materials.begin(), description.materials.end(),
                                      [](const Material& m) { return m.has_textures(); });
    // The shading-normal table exists only if some triangle will read it.
    const bool smooth = std::any_of(description.meshes.begin(), description.meshes.end(), [](const TriangleMesh& m) {
        return !m.normals.empty() && !m.triangles.empty();
    });
    scene.triangles.store_only_for(description.settings.accuracy.triangles);
    scene.triangles.reserve_for(description.meshes);
    for (std::size_t k = 0; k < description.meshes.size(); ++k) {
        const TriangleMesh& mesh = description.meshes[k];
        check_vertex_attribute_counts(mesh, "mesh " + std::to_string(k) + " has");
        if (!as_parallelogram(mesh)) continue;
        const uint32_t first = add_mesh_vertices(mesh.vertices, {}, smooth, scene.triangles, scene.shading_normals);
        scene.triangles.push_parallelogram(first, first + 1, first + 3, mesh.material);
        if (textured) {
            scene.texture_coordinates.add_vertices(mesh.vertices.size(), {}, {}, {});
            scene.texture_coordinates.push_triangle({first, first + 1, first + 3}, 0.0f);
        }
    }
    for (const TriangleMesh& mesh : description.meshes) {
        if (as_parallelogram(mesh)) continue;
        const uint32_t first = add_mesh_vertices(mesh.vertices, mesh.normals, smooth, scene.triangles, scene.shading_normals);
        if (textured) add_texture_vertices(scene.texture_coordinates, mesh);
        for (const auto& tri : mesh.triangles) {
            scene.triangles.push(first + tri[0], first + tri[1], first + tri[2], mesh.material);
            if (textured) push_texture_triangle(scene.texture_coordinates, mesh, first, tri);
        }
    }
    for (const Sphere& sphere : description.spheres) {
        scene.spheres.push_back(sphere.center, sphere.radius, sphere.material);
    }
    build_instances(description, scene.primitive_count(), scene.instances);
    scene.has_rough_materials = std::any_of(scene.materials.begin(), scene.materials.end(),
                                            [](const Material& m) { return m.is_microfacet(); });
    scene.has_alpha_materials = std::any_of(scene.materials.begin(), scene.materials.end(),
                                            [](const Material& m) { return m.is_alpha_tested(); });
    if (textured) {
        for (const TextureImage& image : description.textures) scene.textures.emplace_back(image);
        set_camera_cone(scene, description);
    }
    scene.lights = LightTable(scene.triangles, scene.materials, scene.textures, scene.texture_coordinates);
    // Another selection than by area only where there is a choice: with one emitter they all agree.
    const LightSelection selection = chosen_light_selection(description.settings.estimator.light_selection, scene.lights);
    if (selection != LightSelection::area && scene.lights.size() > 1)
        scene.emitter_selection = EmitterSelection(selection, scene.lights, scene.triangles);
    if (!description.lights.empty() || !scene.emitter_selection.empty()) {
        scene.listed_lights = SceneLights(description.lights, scene.lights.empty() ? 0.0 : area_light_power(scene.triangles, scene.lights),
                                          bounding_sphere(scene));
        if (!scene.lights.empty()) {
            scene.lights.set_selection_probability(scene.listed_lights.area_probability());
            scene.emitter_selection.set_selection_probability(scene.listed_lights.area_probability());
        }
    }
    // The loader refuses degenerate lights, so a description with an emitter has a light table,
    // and one with a "lights" list the list.
    scene.light_traces_caustics = light_traces_caustics(description) && (!scene.lights.empty() || !scene.listed_lights.empty());
    // Photons land only on diffuse surfaces that reflect something: without one there is nothing to gather.
    scene.merges_photons = scene.light_traces_caustics && description.settings.estimator.caustics == CausticPaths::photons &&
                           std::any_of(scene.materials.begin(), scene.materials.end(), [](const Material& m) {
                               return !m.is_specular() && (m.albedo.x > 0.0f || m.albedo.y > 0.0f || m.albedo.z > 0.0f);
                           });
    return scene;
}

}  // namespace wt
