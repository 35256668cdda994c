#include "core/scene_file/scene_schema_instances.h"

#include <cstdio>
#include <utility>

#include "core/system/available_memory.h"

#include "core/instances/build_instances.h"
#include "core/instances/scene_instances.h"
#include "core/scene_file/scene_schema.h"

// The scene file's "meshes" (named meshes, drawn only where instances place them) and the
// "instance" shape. A named mesh is a quad, mesh or mesh_file shape, or itself an instance of
// another name (a grove of trees): nested instances are resolved here into single placements
// of a stored mesh with the transforms composed, so the renderer sees one level.

namespace wt {

// The instance count the top level can index (its leaf references, bvh_view.h).
constexpr uint64_t kMaxInstances = uint64_t(1) << 26;

NamedMeshes::NamedMeshes(const Reader& in, const Json* meshes, SceneDescription& scene, MaterialNames& names)
    : in_(in), scene_(scene), names_(names) {
    if (!meshes) return;
    in.expect_object(*meshes, "meshes");
    for (auto it = meshes->begin(); it != meshes->end(); ++it) {
        Entry e;
        e.json = &it.value();
        e.path = member_path("meshes", it.key());
        entries_.emplace(it.key(), std::move(e));
    }
}

NamedMeshes::Entry& NamedMeshes::resolve(const std::string& name, const std::string& path) {
    const auto it = entries_.find(name);
    if (it == entries_.end()) {
        std::string known;
        for (const auto& [n, e] : entries_) known += (known.empty() ? "" : ", ") + Json(n).dump();
        in_.fail(path, "no mesh named " + Json(name).dump() + " in \"meshes\"" +
                           (known.empty() ? " (the scene defines none)" : " (defined: " + known + ")"));
    }
    Entry& e = it->second;
    if (e.state == State::done) return e;
    if (e.state == State::resolving)
        in_.fail(path, "mesh " + Json(name).dump() + " places itself: a reference cycle through " + e.path);
    e.state = State::resolving;
    const Json& j = *e.json;
    in_.expect_object(j, e.path);
    const Json* type = in_.optional(j, "type");
    if (type && type->is_string() && type->get<std::string>() == "instance") {
        in_.check_keys(j, e.path, {"type", "of", "transforms"}, " for an instance");
        e.placements = expand(j, e.path);
    } else {
        e.placements = read_geometry(name, j, e.path);
    }
    e.triangles = 0;
    for (const Placement& p : e.placements) e.triangles += triangles_of(p.prototype);
    e.state = State::done;
    return e;
}

uint64_t NamedMeshes::triangles_of(uint32_t prototype) const {
    uint64_t n = 0;
    for (const TriangleMesh& part : scene_.prototypes[prototype].parts) n += part.triangles.size();
    return n;
}

std::vector<NamedMeshes::Placement> NamedMeshes::read_geometry(const std::string& name, const Json& j, const std::string& path) {
    const std::size_t first_mesh = scene_.meshes.size(), spheres = scene_.spheres.size();
    const std::size_t first_instance = scene_.instances.size();
    read_shape(in_, j, path, scene_, names_);
    if (scene_.spheres.size() != spheres)
        in_.fail(path, "a named mesh holds triangles only (a quad, mesh or mesh_file), got a sphere");
    std::vector<Placement> placements;
    // A glTF whose nodes share a mesh placed it by instances itself: those are this name's too.
    for (std::size_t k = first_instance; k < scene_.instances.size(); ++k)
        placements.push_back({scene_.instances[k].prototype, scene_.instances[k].transform});
    scene_.instances.resize(first_instance);
    if (scene_.meshes.size() == first_mesh) return placements;
    MeshPrototype proto;
    proto.name = name;
    for (std::size_t i = first_mesh; i < scene_.meshes.size(); ++i) {
        const Material& m = scene_.materials[scene_.meshes[i].material];
        if (m.is_emissive())
            in_.fail(member_path(path, "material"), "an instanced mesh cannot emit (material " + Json(m.name).dump() +
                                                        "): the light table lists the scene's own triangles; "
                                                        "place it as a shape");
        proto.parts.push_back(std::move(scene_.meshes[i]));
    }
    scene_.meshes.resize(first_mesh);
    scene_.prototypes.push_back(std::move(proto));
    placements.push_back({uint32_t(scene_.prototypes.size() - 1), glm::dmat4(1.0)});
    return placements;
}

std::vector<NamedMeshes::Placement> NamedMeshes::expand(const Json& j, const std::string& path) {
    const std::string of_path = member_path(path, "of");
    const std::string name = in_.text(in_.required(j, "of", path), of_path);
    const std::vector<glm::dmat4> transforms = read_transforms(j, path);
    const Entry& inner = resolve(name, of_path);
    const std::string transforms_path = member_path(path, "transforms");
    const uint64_t count = uint64_t(transforms.size()) * inner.placements.size();
    if (count > kMaxInstances)
        in_.fail(transforms_path, std::to_string(transforms.size()) + " placements of " + Json(name).dump() + " (" +
                                      std::to_string(inner.placements.size()) + " instances each) make " + std::to_string(count) +
                                      " instances, more than the " + std::to_string(kMaxInstances) + " a scene can hold");
    if (double(transforms.size()) * double(inner.triangles) > double(kMaxPrimitiveIds))
        in_.fail(transforms_path, std::to_string(transforms.size()) + " placements of " + Json(name).dump() + " (" +
                                      std::to_string(inner.triangles) + " triangles) make more than the " +
                                      std::to_string(kMaxPrimitiveIds) + " triangles a hit's 32-bit id can name");
    check_memory(scene_.instances.size() + count, transforms_path);
    std::vector<Placement> out;
    out.reserve(count);
    for (std::size_t t = 0; t < transforms.size(); ++t)
        for (const Placement& p : inner.placements) {
            const glm::dmat4 m = transforms[t] * p.transform;
            const std::string problem = instance_transform_problem(m);
            if (!problem.empty())
                in_.fail(element_path(transforms_path, t), "composed with the placements of " + Json(name).dump() + ", " + problem);
            out.push_back({p.prototype, m});
        }
    return out;
}

std::vector<glm::dmat4> NamedMeshes::read_transforms(const Json& j, const std::string& path) {
    const std::string transforms_path = member_path(path, "transforms");
    const Json& list = in_.required(j, "transforms", path);
    in_.expect_array(list, transforms_path);
    if (list.empty()) in_.fail(transforms_path, "an instance needs at least one transform, got an empty array");
    if (list.size() > kMaxInstances)
        in_.fail(transforms_path, std::to_string(list.size()) + " transforms, more than the " + std::to_string(kMaxInstances) +
                                      " instances a scene can hold");
    std::vector<glm::dmat4> out;
    out.reserve(list.size());
    for (std::size_t t = 0; t < list.size(); ++t) {
        const std::string element = element_path(transforms_path, t);
        const glm::dmat4 m = read_transform(in_, list[t], element);
        const std::string problem = instance_transform_problem(m);
        if (!problem.empty()) in_.fail(element, problem);
        out.push_back(m);
    }
    return out;
}

// What placing `count` instances costs before the renderer's own estimate can be asked (the
// loader's placements, the description's, then the scene's), so a count that cannot fit is
// refused before it is built.
void NamedMeshes::check_memory(uint64_t count, const std::string& path) const {
    const double bytes = double(count) * double(sizeof(Placement) + sizeof(InstanceDescription) + sizeof(Instance));
    const double available = available_memory_bytes();
    if (available > 0.0 && bytes > 0.5 * available) {
        char text[200];
        std::snprintf(text, sizeof text, "%llu instances need %.1f GB just to be placed, more than half the %.1f GB of memory available",
                      (unsigned long long)count, bytes * 1e-9, available * 1e-9);
        in_.fail(path, text);
    }
}

void NamedMeshes::place(const Json& j, const std::string& path) {
    in_.check_keys(j, path, {"type", "of", "transforms"}, " for an instance");
    const std::vector<Placement> placements = expand(j, path);
    uint64_t triangles = 0;
    for (const Placement& p : placements) triangles += triangles_of(p.prototype);
    if (scene_.instances.size() + placements.size() > kMaxInstances)
        in_.fail(member_path(path, "transforms"), "the scene's instances would number more than " + std::to_string(kMaxInstances));
    if (placed_triangles_ + triangles > kMaxPrimitiveIds)
        in_.fail(member_path(path, "transforms"), "the scene's instances would place more than the " +
                                                      std::to_string(kMaxPrimitiveIds) + " triangles a hit's 32-bit id can name");
    check_memory(scene_.instances.size() + placements.size(), member_path(path, "transforms"));
    placed_triangles_ += triangles;
    for (const Placement& p : placements) scene_.instances.push_back({p.prototype, p.transform});
}

}  // namespace wt
