#pragma once
// The scene file's named meshes and the "instance" shape that places them (see
// scene_schema_instances.cpp). Every message names the JSON path of the field at fault.

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>

#include "core/description/scene_description.h"
#include "core/scene_file/json_reader.h"
#include "core/scene_file/material_names.h"

namespace wt {

class NamedMeshes {
public:
    // `meshes`: the file's "meshes" object, or null. Names are read when first placed, so an
    // unused one costs nothing and its file is never opened.
    NamedMeshes(const Reader& in, const Json* meshes, SceneDescription& scene, MaterialNames& names);
    // An {"type": "instance", "of": NAME, "transforms": [...]} shape: appends its placements to
    // scene.instances (and the meshes they need to scene.prototypes).
    void place(const Json& shape, const std::string& path);

private:
    enum class State { unread, resolving, done };
    struct Placement {
        uint32_t prototype;
        glm::dmat4 transform;
    };
    struct Entry {
        const Json* json = nullptr;
        std::string path;
        State state = State::unread;
        std::vector<Placement> placements;  // what placing this name once places
        uint64_t triangles = 0;
    };

    Entry& resolve(const std::string& name, const std::string& path);
    std::vector<Placement> read_geometry(const std::string& name, const Json& j, const std::string& path);
    uint64_t triangles_of(uint32_t prototype) const;
    std::vector<Placement> expand(const Json& instance, const std::string& path);
    std::vector<glm::dmat4> read_transforms(const Json& instance, const std::string& path);
    void check_memory(uint64_t count, const std::string& path) const;

    const Reader& in_;
    SceneDescription& scene_;
    MaterialNames& names_;
    std::map<std::string, Entry> entries_;
    uint64_t placed_triangles_ = 0;
};

}  // namespace wt
