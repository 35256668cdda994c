#include "core/scene.h"

namespace wt {

Scene build_scene(const SceneDescription& description) {
    Scene scene;
    scene.settings = description.settings;
    scene.camera = Camera(description.camera, description.settings.width, description.settings.height);
    scene.materials = description.materials;
    for (const TriangleMesh& mesh : description.meshes) {
        for (const auto& tri : mesh.triangles) {
            scene.triangles.push_back(mesh.vertices[tri[0]], mesh.vertices[tri[1]], mesh.vertices[tri[2]], mesh.material);
        }
    }
    for (const Sphere& sphere : description.spheres) {
        scene.spheres.push_back(sphere.center, sphere.radius, sphere.material);
    }
    scene.lights = LightTable(scene.triangles, scene.materials);
    return scene;
}

}  // namespace wt
