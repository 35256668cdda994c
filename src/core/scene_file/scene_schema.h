#pragma once
// The scene file's sections, each read from its JSON value into the SceneDescription with every
// key checked. `path` is the JSON path of the value, for messages ("shapes[2].radius").

#include <cstdint>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>

#include "core/scene_file/json_reader.h"
#include "core/scene_file/material_names.h"
#include "core/description/scene_description.h"

namespace wt {

// The camera, written out or taken from a glTF file ("gltf"); `render` (the image size) and
// `notes` for what a glTF camera asks that the image does not give.
CameraDescription read_camera(const Reader& in, const Json& j, const std::string& path, const RenderSettings& render,
                              std::vector<std::string>& notes);
// {"gltf": FILE, "name" or "index", "transform", and the thin lens's keys} (scene_schema_camera_gltf.cpp).
CameraDescription read_gltf_camera_section(const Reader& in, const Json& j, const std::string& path,
                                           const RenderSettings& render, std::vector<std::string>& notes);
// A perspective camera's aperture_radius, and focus_distance or focus_on (the plane in focus
// through a point, square to the view axis from camera.eye to camera.look_at).
void read_thin_lens(const Reader& in, const Json& j, const std::string& path, CameraDescription& camera);
RenderSettings read_render(const Reader& in, const Json& j, const std::string& path);
// Textures the materials name are appended to `textures`.
std::vector<Material> read_materials(const Reader& in, const Json& j, const std::string& path,
                                     std::vector<TextureImage>& textures);
// A colour in [0, 1] ([r, g, b]), or {"texture": FILE, "factor": [r, g, b], "wrap": MODE}: then
// the image is read (relative to the scene file), appended to `textures`, `texture` set to its
// index, and the factor (white by default) returned. at_most_one false: the colour and the
// factor may exceed 1 (an emission).
glm::vec3 read_color_or_texture(const Reader& in, const Json& j, const std::string& path, std::vector<TextureImage>& textures,
                                int32_t& texture, bool at_most_one = true);
// The index of the material named by the string j; fails naming the materials defined.
uint32_t find_material(const Reader& in, const std::vector<Material>& materials, MaterialNames& names,
                       const Json& j, const std::string& path);
// A zero-area light would vanish from the light table without a word: fails naming it.
void check_light_triangles(const Reader& in, const TriangleMesh& mesh, const std::string& path);
// A shape's "transform" object (scale, then rotate, then translate; or a 4x4 matrix).
glm::dmat4 read_transform(const Reader& in, const Json& j, const std::string& path);
// "type": "mesh_file": the file is found relative to the scene file's directory.
void read_mesh_file_shape(const Reader& in, const Json& j, const std::string& path, SceneDescription& scene,
                          MaterialNames& names);
// The "lights" list (environment maps are read here, relative to the scene file's directory).
std::vector<LightDescription> read_lights(const Reader& in, const Json& j, const std::string& path);
// One quad, mesh, sphere or mesh_file shape (not an instance): appends to scene.meshes or
// scene.spheres (and to scene.materials and scene.notes, for mesh files).
void read_shape(const Reader& in, const Json& j, const std::string& path, SceneDescription& scene, MaterialNames& names);
// Needs scene.materials; appends to scene.meshes and scene.spheres (and to scene.materials and
// scene.notes, for mesh files), and for instances to scene.prototypes and scene.instances.
// `meshes`: the file's "meshes" object (named meshes for instances), or null.
void read_shapes(const Reader& in, const Json& j, const std::string& path, SceneDescription& scene,
                 const Json* meshes = nullptr);

}  // namespace wt
