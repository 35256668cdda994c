#include "core/scene.h"

namespace wt {

Scene build_scene(const SceneDescription& description) {
    Scene scene;
    scene.settings = description.settings;
    scene.camera = Camera(description.camera, description.settings.width, description.settings.height);
    scene.materials = description.materials;
    // Parallelograms first (TriangleSoA keeps them as a prefix), and only for the test that
    // knows them.
    const bool parallelograms = description.settings.accuracy.triangles == TriangleTest::moller_trumbore;
    auto as_parallelogram = [&](const TriangleMesh& m) { return parallelograms && m.parallelogram; };
    for (const TriangleMesh& mesh : description.meshes) {
        if (as_parallelogram(mesh))
            scene.triangles.push_parallelogram(mesh.vertices[0], mesh.vertices[1], mesh.vertices[3], mesh.material);
    }
    for (const TriangleMesh& mesh : description.meshes) {
        if (as_parallelogram(mesh)) continue;
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
