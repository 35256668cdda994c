#pragma once
// What a scene file says, before it is flattened into the SoA buffers the kernels read
// (see scene.h). Plain data: the loader fills it, build_scene() consumes it, tests build it in code.

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <memory>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "core/base/accuracy.h"
#include "core/description/adaptive_settings.h"
#include "core/description/estimator_settings.h"
#include "core/description/pixel_filter_settings.h"
#include "core/textures/texture_image.h"

namespace wt {

// The specular types (mirror ... conductor) are consecutive, and the rough ones last, so each
// test is one comparison. A scene file's "conductor" and "rough_glass" with roughness 0 load as
// conductor and glass (core/materials/microfacet_material.h).
enum class MaterialType : uint8_t {
    lambertian,       // albedo / pi
    oren_nayar,       // qualitative Oren-Nayar 1994, roughness sigma in radians
    mirror,           // perfect specular reflection, tinted by reflectance
    glass,            // smooth dielectric: Snell refraction, Schlick Fresnel, total internal reflection
    conductor,        // smooth metal: perfect specular reflection with a conductor's Fresnel term
    rough_conductor,  // GGX microfacet metal (core/materials/rough_conductor.h)
    rough_glass,      // GGX microfacet dielectric, reflection and refraction (core/materials/rough_dielectric.h)
    principled,       // glTF 2.0 metallic-roughness: Lambert and GGX mixed by metallic (core/materials/principled.h)
};

enum class AlphaMode : uint8_t { opaque, mask, blend };

struct Material {
    std::string name;
    MaterialType type = MaterialType::lambertian;
    glm::vec3 albedo{0.0f};       // lambertian, oren_nayar
    float sigma = 0.0f;           // oren_nayar roughness (radians)
    glm::vec3 reflectance{1.0f};  // mirror
    float ior = 1.5f;             // glass, relative to the surrounding medium (vacuum)
    glm::vec3 emission{0.0f};     // radiance leaving the front face (diffuse and principled materials only)
    // glTF's emissiveTexture (3.9.5, colour): its RGB multiplies emission at each point of the
    // surface, at hits and at light samples alike (core/lights/light_table.h); or -1.
    int32_t emission_texture = -1;
    // conductor, rough_conductor, rough_glass (which also reads ior):
    float roughness = 0.0f;       // perceptual, in [0, 1]: the GGX alpha is roughness^2, as in glTF
    glm::vec3 f0{1.0f};           // conductors: reflectance at normal incidence (Schlick)
    glm::vec3 eta{0.0f}, k{0.0f}; // conductors: complex index of refraction, used instead of f0 when eta.x > 0
    // principled (which also reads roughness, ior and emission). Not albedo: the diffuse
    // materials' light sampler and the photons read that, and this lobe is not theirs.
    glm::vec3 base_color{0.0f};   // glTF's baseColorFactor, in [0, 1]
    float metallic = 0.0f;        // glTF's metallicFactor, in [0, 1]
    // Index into SceneDescription::textures, or -1: multiplies albedo (diffuse materials),
    // base_color (principled) or f0 (conductors) at each hit (core/scene/material_at_hit.h).
    int32_t color_texture = -1;
    // principled only: glTF's metallicRoughnessTexture, its blue channel multiplying metallic
    // and its green one roughness (linear data, not colour).
    int32_t metallic_roughness_texture = -1;
    // A tangent-space normal map (glTF's normalTexture, linear data): RGB 2 c - 1 is the normal
    // about the mesh's vertex tangents (TriangleMesh::tangents) where it has them, else the
    // triangle's tangent frame (core/geometry/texture_coordinates.h), x and y times
    // normal_scale; it replaces the shading normal. Triangles with texture coordinates only.
    int32_t normal_texture = -1;
    float normal_scale = 1.0f;
    // glTF 2.0's alphaMode (3.9.4): opaque ignores alpha; mask, a hit whose alpha is below
    // alpha_cutoff is no hit; blend, a hit is kept with probability alpha (stochastic
    // transparency). alpha = alpha_factor times alpha_texture's alpha (the base colour texture's,
    // glTF's baseColorTexture, or -1) at the hit's coordinates. Tested inside traversal, for
    // every ray (core/scene/alpha_test.h).
    AlphaMode alpha_mode = AlphaMode::opaque;
    float alpha_factor = 1.0f;   // in [0, 1]
    float alpha_cutoff = 0.5f;   // mask only, >= 0
    int32_t alpha_texture = -1;
    // Set by build_scene from settings.accuracy.multiple_scattering, never by the loaders: the
    // GGX reflection lobe of a rough_conductor or principled material gets Kulla & Conty's
    // multiple-scattering lobe (core/materials/multiple_scattering.h). A conductor given by its
    // complex index needs its Fresnel term's cosine-weighted average for that, computed once here;
    // Schlick's has a closed form, taken at each hit (a texture may change f0).
    bool multiple_scattering = false;
    glm::vec3 conductor_fresnel_average{0.0f};

    bool has_textures() const {
        return color_texture >= 0 || metallic_roughness_texture >= 0 || normal_texture >= 0 || alpha_texture >= 0 ||
               emission_texture >= 0;
    }
    bool is_alpha_tested() const { return alpha_mode != AlphaMode::opaque; }
    bool is_emissive() const { return emission.x > 0.0f || emission.y > 0.0f || emission.z > 0.0f; }
    bool is_specular() const { return type >= MaterialType::mirror && type <= MaterialType::conductor; }
    // A GGX lobe: neither diffuse nor specular (light samples and BSDF samples, never connected
    // to the camera by light tracing nor a photon gather point; core/path/path_vertex.h).
    bool is_microfacet() const { return type >= MaterialType::rough_conductor; }
};

// Triangles index into `vertices`. Winding defines the front face: the geometric normal is
// cross(v1 - v0, v2 - v0), and only the front face of an emissive triangle emits.
struct TriangleMesh {
    std::vector<glm::vec3> vertices;
    std::vector<std::array<uint32_t, 3>> triangles;
    uint32_t material = 0;  // index into SceneDescription::materials
    // A quad [v0, v1, v2, v3] whose corner v2 is exactly v1 + v3 - v0 in float (rectangles on
    // grid coordinates, like the hexroom's walls and light). Its triangles are (0,1,2), (0,2,3),
    // and build_scene() may store it as one parallelogram instead: one test where two were.
    bool parallelogram = false;
    // Shading normals, one per vertex (unit length), interpolated across each triangle; empty
    // for a flat-shaded mesh, which shades with the geometric normal. Ray offsets and the
    // side a ray is on always use the geometric normal.
    std::vector<glm::vec3> normals;
    // Texture coordinates, one per vertex (glTF's TEXCOORD_0; OBJ's vt with v flipped, so v = 0
    // is the image's top row in both), or empty. Read only when some material has a texture.
    std::vector<glm::vec2> uvs;
    // glTF's TEXCOORD_1, one per vertex, read by the textures whose coordinate_set is 1; empty
    // unless some material of the mesh has such a texture.
    std::vector<glm::vec2> second_uvs;
    // Normal-map tangents, one per vertex, as glTF's TANGENT: xyz unit, w = +1 or -1 the side of
    // the bitangent cross(normal, xyz) w; w = 0 where a vertex has none (its triangle uses its
    // own frame). Empty unless a normal-mapped material's mesh came with or was given them.
    std::vector<glm::vec4> tangents;
};

// A named mesh that instances place (the scene file's "meshes"; a glTF mesh used by several
// nodes): its parts, one per material, in its own (object) coordinates. Drawn only by instances.
struct MeshPrototype {
    std::string name;
    std::vector<TriangleMesh> parts;
};

// One placement of a prototype: object -> world, affine and invertible (the loader checks).
struct InstanceDescription {
    uint32_t prototype = 0;  // index into SceneDescription::prototypes
    glm::dmat4 transform{1.0};
};

struct Sphere {
    glm::vec3 center{0.0f};
    float radius = 1.0f;
    uint32_t material = 0;
};

// Pinhole camera. fov_degrees is the vertical field of view; the horizontal one follows
// from the image's aspect ratio. Screen right is cross(look direction, up).
// A light of the scene file's "lights" list (README, "Lights"), beside the emissive materials.
// Units: radiance W/(m^2 sr), intensity W/sr, irradiance W/m^2.
enum class LightType : uint8_t { environment, point, spot, directional };

// An equirectangular map's texels, linear RGB, rows from +z (top) to -z (bottom).
struct EnvironmentMap {
    int width = 0, height = 0;
    std::vector<float> rgb;  // width * height * 3, interleaved
};

struct LightDescription {
    LightType type = LightType::point;
    glm::vec3 radiance{0.0f};   // environment without a map: constant radiance
    std::string file;           // environment with a map: the file as the scene names it
    std::shared_ptr<const EnvironmentMap> map;  // its texels, read by the loader
    float strength = 1.0f;      // scales the map
    float rotate_degrees = 0.0f;  // turns the map about +z
    glm::vec3 position{0.0f};   // point, spot
    glm::vec3 intensity{0.0f};  // point, spot (on the axis)
    glm::vec3 direction{0.0f, 0.0f, -1.0f};  // spot: its axis; directional: where the light travels (unit)
    float cone_degrees = 90.0f;  // spot: full opening angle, in (0, 180]
    float blend = 0.0f;          // spot: fraction of the cone over which it fades out, [0, 1]
    glm::vec3 irradiance{0.0f};  // directional: on a surface facing it
    float angle_degrees = 0.0f;  // directional: angular diameter of the source, [0, 180); 0 = a delta
};

enum class Projection : uint8_t {
    perspective,   // a pinhole, or a thin lens with aperture_radius > 0
    orthographic,  // parallel rays along the view axis from a window width_world wide
};

struct CameraDescription {
    glm::vec3 eye{0.0f};
    glm::vec3 look_at{1.0f, 0.0f, 0.0f};
    glm::vec3 up{0.0f, 0.0f, 1.0f};
    float fov_degrees = 90.0f;  // perspective: the vertical field of view
    Projection projection = Projection::perspective;
    // Thin lens (perspective only): 0 is the pinhole. Points at focus_distance along the view
    // axis are sharp; 0 there means |look_at - eye| (the loader resolves "focus_on" into it).
    float aperture_radius = 0.0f;
    float focus_distance = 0.0f;
    float width_world = 0.0f;  // orthographic: the image's width in scene units
};

struct RenderSettings {
    int width = 800;
    int height = 800;
    int spp = 64;            // samples per pixel
    // M: light samples per diffuse hit. One, as in pbrt and Cycles: a scene whose error is in
    // its indirect light (the hexroom's caustics) gains nothing from more, at their full cost
    // (README, "The hexroom's trade").
    int shadow_rays = 1;
    uint64_t seed = 0;       // every random number is keyed by (seed, pixel, sample, bounce, dim)
    int max_bounces = 64;    // hard cap; Russian roulette ends almost every path long before
    int rr_start_bounce = 3; // first bounce at which Russian roulette may end a path
    AccuracySettings accuracy;
    EstimatorSettings estimator;
    AdaptiveSettings adaptive;  // off by default
    PixelFilterSettings filter;  // box of width 1: each sample uniform in its pixel
};

struct SceneDescription {
    CameraDescription camera;
    RenderSettings settings;
    std::vector<Material> materials;
    std::vector<TriangleMesh> meshes;
    std::vector<Sphere> spheres;
    std::vector<MeshPrototype> prototypes;   // usually empty: meshes stored once, placed by instances
    std::vector<InstanceDescription> instances;
    std::vector<LightDescription> lights;  // beside the emissive materials; usually empty
    std::vector<TextureImage> textures;    // what Material::color_texture and the like index
    // One line each, for the user, about what the loader skipped or could not map (degenerate
    // triangles dropped from a mesh file, its textures, ...); never an error. The CLI prints them.
    std::vector<std::string> notes;
};

}  // namespace wt
