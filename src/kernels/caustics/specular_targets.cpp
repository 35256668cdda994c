#include "kernels/caustics/specular_targets.h"

#include <limits>

#include "kernels/primitives/primitive_intersect.h"

namespace wt {

std::optional<SpecularTargets> SpecularTargets::of(const Scene& scene) {
    const auto specular = [&](uint32_t material) { return scene.materials[material].is_specular(); };
    for (const InstancedMesh& mesh : scene.instances.meshes)
        for (uint32_t material : mesh.triangles.material)
            if (specular(material)) return std::nullopt;
    SpecularTargets t;
    t.scene_ = &scene;
    for (uint32_t i = 0; i < scene.triangles.size(); ++i)
        if (specular(scene.triangles.material[i])) {
            if (t.triangles_.size() == kMostPrimitives) return std::nullopt;
            t.triangles_.push_back(i);
        }
    for (uint32_t i = 0; i < scene.spheres.size(); ++i)
        if (specular(scene.spheres.material[i])) {
            if (t.triangles_.size() + t.spheres_.size() == kMostPrimitives) return std::nullopt;
            t.spheres_.push_back(i);
            t.sphere_x_.push_back(scene.spheres.cx[i]), t.sphere_y_.push_back(scene.spheres.cy[i]);
            t.sphere_z_.push_back(scene.spheres.cz[i]), t.sphere_radius_.push_back(scene.spheres.radius[i]);
        }
    t.triangle_rows_ = triangle_rows(scene.triangles, t.triangles_);
    return t;
}

SceneView SpecularTargets::view() const {
    return {triangle_view(triangle_rows_),
            {sphere_x_.data(), sphere_y_.data(), sphere_z_.data(), sphere_radius_.data(), uint32_t(spheres_.size()),
             triangle_rows_.count}};
}

bool SpecularTargets::may_hit(const Ray& ray) const {
    const Scene& scene = *scene_;
    const AccuracySettings& accuracy = scene.settings.accuracy;
    Hit hit;
    hit.t = std::numeric_limits<float>::infinity();
    if (accuracy.triangles == TriangleTest::watertight) {
        const WatertightRay w = watertight_ray(ray.direction);
        for (uint32_t i : triangles_)
            if (intersect_triangle_watertight(scene.triangles, i, ray, w, hit)) return true;
    } else {
        for (uint32_t i : triangles_)
            if (intersect_triangle(scene.triangles, i, ray, hit)) return true;
    }
    const uint32_t first_sphere = uint32_t(scene.triangles.size());
    for (uint32_t i : spheres_) {
        const bool found = accuracy.spheres == SphereTest::cancellation_free
                               ? intersect_sphere_cancellation_free(scene.spheres, i, first_sphere + i, ray, hit)
                               : intersect_sphere(scene.spheres, i, first_sphere + i, ray, hit);
        if (found) return true;
    }
    return false;
}

}  // namespace wt
