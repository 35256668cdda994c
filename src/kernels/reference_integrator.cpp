#include "kernels/reference_integrator.h"

#include "core/path/glossy_light_sampler.h"
#include "core/path/listed_light_sampler.h"
#include "core/scene/material_at_hit.h"
#include "core/path/path_vertex.h"
#include "kernels/isa/bvh_single_ray.h"
#include "kernels/photons/photon_gather.h"
#include "kernels/photons/photon_maps.h"
#include "kernels/accel/scene_intersect.h"

namespace wt {

namespace {

// kListedLights: the scene has a "lights" list (Scene::listed_lights), whose samplers and escaped
// rays the loop runs instead of the area lights' alone; chosen once per path.
template <typename E, bool kListedLights>
glm::vec3 trace_path(const Scene& scene, uint32_t pixel, uint32_t sample, RayCounts& counts,
                     std::vector<PathVertexRecord>* record, const BvhView* bvh, FirstSurface* first_surface,
                     const PhotonMaps* photons) {
    const AccuracySettings& accuracy = scene.settings.accuracy;
    auto closest = [&](const Ray& r) { return bvh ? bvh_intersect_closest(*bvh, accuracy, r) : intersect_closest(scene, r); };
    auto blocked = [&](const Ray& r, float tmax) {
        return bvh ? bvh_intersect_any(*bvh, accuracy, r, tmax) : intersect_any(scene, r, tmax);
    };
    const PathSeed path = path_seed<E>(scene, pixel, sample);
    const uint32_t shadow_ray_count = uint32_t(scene.settings.shadow_rays);
    const CameraRay camera = camera_ray<E>(scene, pixel, path);
    Ray ray = camera.ray;
    ++counts.camera_rays;
    glm::vec3 radiance(0.0f);
    glm::vec3 throughput(1.0f);
    bool count_emission = true;  // camera rays, specular bounces (no light sample covered them), any with mis
    float bsdf_pdf = 0.0f;       // mis: see emission_added
    bool specular_light_elsewhere = false;  // light tracing only: PathContinuation::specular_light_elsewhere
    [[maybe_unused]] bool count_environment = true;  // kListedLights: PathContinuation::count_environment
    glm::vec3 previous_normal(0.0f);  // kListedLights: the geometric normal of the vertex that cast `ray`

    std::optional<Material> textured;  // the hit's material with its textures looked up (core/scene/material_at_hit.h)
    for (uint32_t bounce = 0;; ++bounce) {
        const Hit hit = closest(ray);
        if (!hit.found()) {
            if constexpr (kListedLights)
                if (count_environment && scene.listed_lights.seen_by_escaping_rays())
                    radiance += escaped_radiance<E>(scene, ray.direction, throughput, bsdf_pdf, bounce);
            break;
        }
        SurfacePoint surface = surface_at(scene, ray, hit);  // a normal map may change its shading normal
        const Material& m = material_at(scene, hit, surface, ray, bounce == 0, textured);
        if (first_surface && !first_surface->found)
            record_first_surface(*first_surface, scene.camera, bounce, ray, hit, surface, m, throughput);
        PathVertexRecord vertex{bounce, hit, surface.position, surface.normal, surface.shading_normal, surface.material,
                                throughput, glm::vec3(0.0f), 0, 0, glm::vec3(0.0f), 0.0f, 0, glm::vec3(0.0f)};

        if (count_emission) {
            vertex.emission_added = emission_added<E, true, kListedLights>(scene, m, surface, ray, hit.t, throughput, bsdf_pdf,
                                                                           bounce, hit.prim, previous_normal);
            radiance += vertex.emission_added;
        }
        if (photons && gathers_photons(scene, m, bounce, specular_light_elsewhere)) {
            const PhotonGrid& map = photons->map(sample);
            const PhotonGather g = gather_photons(map, m, surface, ray.direction, photon_vertex_limit(scene, bounce));
            vertex.photon_radius = map.radius();
            vertex.photons_gathered = g.photons;
            vertex.photons_added = throughput * g.radiance;
            radiance += vertex.photons_added;
        }
        const auto add_light_sample = [&](const ShadowRay& shadow) {
            ++counts.shadow_rays;
            ++vertex.shadow_rays_traced;
            if (blocked(shadow.ray, shadow.tmax)) return;
            ++vertex.shadow_rays_unoccluded;
            vertex.direct_added += shadow.contribution;
            radiance += shadow.contribution;
        };
        if constexpr (kListedLights) {
            sample_listed_lights<E>(scene, m, surface, ray.direction, throughput, path, bounce, add_light_sample);
        } else if (!scene.lights.empty() && gathers_direct_light(m)) {
            const DirectLightSampler<E> lights(scene, m, surface, light_sampling_point(surface, ray.direction),
                                               ray.direction, throughput, path, bounce, shadow_ray_count);
            lights.sample_all(add_light_sample);
        } else if (!scene.lights.empty() && m.is_microfacet()) {
            GlossyLightSampler<E>(scene, m, surface, ray.direction, throughput, path, bounce, shadow_ray_count)
                .sample_all(add_light_sample);
        }
        if (record) record->push_back(vertex);

        const auto next =
            continue_path<E>(scene, m, surface, ray.direction, throughput, path, bounce, specular_light_elsewhere);
        if (!next) break;
        ++counts.bounce_rays;
        ray = next->ray;
        throughput = next->throughput;
        count_emission = next->count_emission;
        specular_light_elsewhere = next->specular_light_elsewhere;
        bsdf_pdf = next->bsdf_pdf;
        count_environment = next->count_environment;
        if constexpr (kListedLights) previous_normal = surface.normal;
    }
    // The pixel filter's weight, as the wavefront film loop applies it (wavefront_renderer.cpp).
    return radiance * camera.weight;
}

template <typename E>
void render_pixel(const Scene& scene, uint32_t pixel, uint32_t sample_begin, uint32_t sample_end, Film& film,
                  RayCounts& counts, const BvhView* bvh, const AovSelection& aovs, const PhotonMaps* photons) {
    const bool with_aovs = aovs.needs_path_data();
    for (uint32_t s = sample_begin; s < sample_end; ++s) {
        FirstSurface first;
        FirstSurface* aov = with_aovs ? &first : nullptr;
        const glm::vec3 radiance = scene.listed_lights.empty()
                                       ? trace_path<E, false>(scene, pixel, s, counts, nullptr, bvh, aov, photons)
                                       : trace_path<E, true>(scene, pixel, s, counts, nullptr, bvh, aov, photons);
        ++counts.samples;
        float extra[Film::max_extra_channels];
        if (with_aovs) aov_sample_values(aovs, first, extra);
        if (!film.add_sample(pixel, radiance, with_aovs ? extra : nullptr)) ++counts.nonfinite_samples;
    }
}

template <typename E>
void render_tile(const Scene& scene, const Tile& tile, uint32_t sample_begin, uint32_t sample_end, Film& film,
                 RayCounts& counts, const BvhView* bvh, const AovSelection& aovs, const PhotonMaps* photons) {
    for (int y = tile.y0; y < tile.y1; ++y)
        for (int x = tile.x0; x < tile.x1; ++x)
            render_pixel<E>(scene, uint32_t(y) * uint32_t(scene.settings.width) + uint32_t(x), sample_begin, sample_end,
                            film, counts, bvh, aovs, photons);
}

}  // namespace

glm::vec3 trace_reference_path(const Scene& scene, uint32_t pixel, uint32_t sample, RayCounts& counts,
                               std::vector<PathVertexRecord>* record, const BvhView* bvh, FirstSurface* first_surface,
                               const PhotonMaps* photons) {
    return with_estimator(scene.settings.estimator, [&](auto estimator) {
        using E = decltype(estimator);
        return scene.listed_lights.empty() ? trace_path<E, false>(scene, pixel, sample, counts, record, bvh, first_surface, photons)
                                           : trace_path<E, true>(scene, pixel, sample, counts, record, bvh, first_surface, photons);
    });
}

void render_reference_tile(const Scene& scene, const Tile& tile, uint32_t sample_begin, uint32_t sample_end, Film& film,
                           RayCounts& counts, const BvhView* bvh, const AovSelection& aovs, const PhotonMaps* photons) {
    with_estimator(scene.settings.estimator, [&](auto estimator) {
        render_tile<decltype(estimator)>(scene, tile, sample_begin, sample_end, film, counts, bvh, aovs, photons);
    });
}

void render_reference_pixels(const Scene& scene, TilePixels pixels, uint32_t sample_begin, uint32_t sample_end,
                             Film& film, RayCounts& counts, const BvhView* bvh, const AovSelection& aovs,
                             const PhotonMaps* photons) {
    with_estimator(scene.settings.estimator, [&](auto estimator) {
        for (std::size_t i = 0; i < pixels.count; ++i)
            render_pixel<decltype(estimator)>(scene, pixels.index[i], sample_begin, sample_end, film, counts, bvh, aovs,
                                              photons);
    });
}

}  // namespace wt
