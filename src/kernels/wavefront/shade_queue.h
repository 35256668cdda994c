#pragma once
// The shade stage's loop over a queue, for one estimator, with or without recording the AOVs'
// first surface. Included by stage_shade.cpp (the default estimator without AOVs),
// stage_shade_options.cpp (the other estimators without them), stage_shade_aovs.cpp (the
// default with them) and stage_shade_options_aovs.cpp (the others with them): a render without
// AOVs runs the loop it ran before they existed, compiled as it was.

#include <algorithm>
#include <type_traits>

#include "core/path/first_surface.h"
#include "core/path/glossy_light_sampler.h"
#include "core/path/listed_light_sampler.h"
#include "core/scene/material_at_hit.h"
#include "core/path/path_vertex.h"
#include "kernels/isa/shade_kernels.h"
#include "kernels/queues/diffuse_vertex_queue.h"
#include "kernels/queues/ray_queues.h"
#include "kernels/photons/photon_gather.h"
#include "kernels/photons/photon_maps.h"
#include "kernels/wavefront/camera_specular_vertex.h"
#include "kernels/wavefront/stages.h"

namespace wt {

// The same vertex logic as trace_reference_path, in the same order (emission, then light
// samples, then the continuation; the photons' estimate, where one is gathered, after the
// emission), so both integrators add a path's terms identically. kRough: the scene has rough
// (microfacet) materials (Scene::has_rough_materials), whose vertices are tested for at run
// time; without them the loop compiles as it did before they existed (stage_shade_rough.cpp).
// Scenes with textures run it too: it looks the materials up through material_at().
// kListedLights: the scene has a "lights" list (Scene::listed_lights): its light samplers, and
// what escaping rays see, in place of the area lights' alone (stage_shade_listed_lights.cpp,
// always with kRough: a scene with a lights list is rare enough to test its materials at run
// time, and a fourth set of instantiations would cost every build for nothing).
// The SIMD shade kernels (kernels/shading, the ISA's widest vector) take the common vertices: in
// scenes without instances the surface points, a chunk of hits at a time; the
// diffuse vertices' light samples and continuations (flat, or folded about a shading normal),
// for which the loop draws the random
// numbers, picks the light points and queues them in `chunks.diffuse`, and the kernels append
// shadow rays and next rays, a chunk at a time, among the other vertices'; the flat mirror and
// glass vertices' continuations the same way, through `chunks.specular`. Every path's terms
// are still added in the same order (its emission and photons here, its light samples in index
// order by the shadow stage), and each path's random numbers depend on the path alone, so the
// order of the queues changes no bit of the image. Not with a lights list, whose samplers and
// continuations are other code. With a sampler whose numbers are VertexRandom's hashes (the
// default's), the diffuse vertices are queued undrawn and the kernels draw a chunk's numbers at
// once (kernels/shading/diffuse_random.h), and turn the light samples' numbers into points as
// light_sample_point does (kernels/shading/light_points.h; for a table of many or textured
// emitters the loop does, DiffuseVertexQueue::pick_light_points).
template <typename E, bool kRecordAovs, bool kRough, bool kListedLights = false>
void shade_queue(const Scene& scene, const ShadeKernels& kernels, uint32_t bounce, const RayQueue& rays, const HitQueue& hits,
                 PathTable& paths, ShadeChunks& chunks, RayQueue& next_rays, ShadowQueue& shadows,
                 const PhotonMaps* photons) {
    const uint32_t shadow_ray_count = uint32_t(scene.settings.shadow_rays);
    const bool has_lights = !scene.lights.empty();
    const bool path_continues = int(bounce) + 1 < scene.settings.max_bounces;
    // One lane gains nothing from a kernel and pays for its queue: the scalar kernels' loop is the
    // plain one (their width-1 shade kernels are the tests' and the perf gate's reference).
    const bool vector_kernels = kernels.width > 1;
    const bool surface_kernel = vector_kernels;
    const uint32_t surface_kernel_ids_end = surface_kernel_ids(scene);
    SurfaceChunk& surfaces = chunks.surfaces;
    DiffuseVertexQueue& diffuse = chunks.diffuse;
    SpecularVertexQueue& specular = chunks.specular;
    next_rays.count = 0;
    shadows.count = 0;
    diffuse.clear();
    specular.count = 0;
    constexpr bool kDrawsInKernels = std::is_base_of_v<VertexRandom, typename E::Sampler>;
    static_assert(!kDrawsInKernels || E::Sampler::kCheapDraws, "pick_light_points draws every light choice");
    const bool light_points_in_kernels = has_lights && scene.lights.few_untextured_emitters();
    [[maybe_unused]] const auto shade_diffuse_chunk = [&] {
        if constexpr (kDrawsInKernels) {
            kernels.draw_diffuse_random(diffuse, has_lights ? shadow_ray_count : 0);
            if (light_points_in_kernels) kernels.pick_light_points(diffuse, scene.lights, shadow_ray_count);
            else if (has_lights) diffuse.pick_light_points(scene, shadow_ray_count);
        }
        if (has_lights) {
            const DiffuseLightSampling sampling{shadow_ray_count, E::mis && path_continues,
                                                light_sample_clamp_limit<E>(scene, bounce, shadow_ray_count)};
            kernels.sample_diffuse_lights(diffuse, sampling, shadows);
        }
        if (path_continues) {
            const DiffuseContinuation continuation{int(bounce) >= scene.settings.rr_start_bounce, E::mis,
                                                   bounce == 0 ? scene.light_traces_caustics : scene.merges_photons};
            kernels.continue_diffuse(diffuse, continuation, next_rays);
        }
        diffuse.clear();
    };
    [[maybe_unused]] const auto shade_specular_chunk = [&] {
        kernels.continue_specular(specular, int(bounce) >= scene.settings.rr_start_bounce, scene.settings.accuracy.fresnel,
                                  next_rays);
        specular.count = 0;
    };
    [[maybe_unused]] std::optional<Material> textured;  // kRough: the hit's material with its textures looked up
    for (std::size_t i = 0; i < rays.count; ++i) {
        const std::size_t in_chunk = i % SurfaceChunk::kSize;
        if (surface_kernel && in_chunk == 0)
            kernels.surface_points(scene, rays, hits, i, std::min(SurfaceChunk::kSize, rays.count - i), surfaces);
        const Hit hit = hits.hit(i);
        if constexpr (!kListedLights) {
            if (!hit.found()) continue;  // no environment light: the path ends with what it has
        } else if (!hit.found()) {
            const uint8_t flags = rays.count_emission[i];
            if ((bounce == 0 || (flags & RayQueue::kCountEnvironment)) && scene.listed_lights.seen_by_escaping_rays())
                paths.add_radiance(rays.path[i], escaped_radiance<E>(scene, glm::vec3(rays.dx[i], rays.dy[i], rays.dz[i]),
                                                                     rays.throughput(i),
                                                                     E::mis || (flags & RayQueue::kRoughPdf) ? rays.bsdf_pdf[i] : 0.0f,
                                                                     bounce));
            continue;
        }
        const Ray ray = rays.ray(i);
        const uint32_t slot = rays.path[i];
        const PathSeed path{paths.key[slot], paths.sample[slot]};
        const glm::vec3 throughput = rays.throughput(i);
        // (Not const: a normal map may change its shading normal.)
        SurfacePoint surface = surface_kernel && hit.prim < surface_kernel_ids_end ? surfaces.at(in_chunk)
                                                                                   : surface_at(scene, ray, hit);
        // Textured scenes run the kRough loop (stage_shade.cpp): without it, the loop is as it was.
        const Material& m = kRough ? material_at(scene, hit, surface, ray, bounce == 0, textured)
                                   : scene.materials[surface.material];

        if constexpr (kRecordAovs) {
            FirstSurface& first = paths.first_surface[slot];
            if (!first.found) record_first_surface(first, scene.camera, bounce, ray, hit, surface, m, throughput);
        }
        const uint8_t flags = rays.count_emission[i];
        if (flags & RayQueue::kCountEmission)
            paths.add_radiance(slot, emission_added<E, kRough, kListedLights>(scene, m, surface, ray, hit.t, throughput,
                                                                              E::mis || (kRough && (flags & RayQueue::kRoughPdf))
                                                                                  ? rays.bsdf_pdf[i]
                                                                                  : 0.0f,
                                                                              bounce, hit.prim,
                                                                              kListedLights && !scene.emitter_selection.empty()
                                                                                  ? paths.normal(slot)
                                                                                  : glm::vec3(0.0f)));
        const bool elsewhere = flags & RayQueue::kSpecularLightElsewhere;
        if (photons && gathers_photons(scene, m, bounce, elsewhere))
            paths.add_radiance(slot, throughput * gather_photons(photons->map(path.sample), m, surface, ray.direction,
                                                                 photon_vertex_limit(scene, bounce))
                                                      .radiance);
        if constexpr (!kListedLights) {
            if (vector_kernels && continues_as_diffuse(m)) {  // the shade kernels' vertex
                const bool samples_lights = has_lights && gathers_direct_light(m);
                if (!samples_lights && !path_continues) continue;
                const typename E::Sampler random(path, bounce, shadow_ray_count);
                if constexpr (kDrawsInKernels) {
                    diffuse.push_undrawn(surface, m, ray.direction, throughput, random.base, slot, elsewhere, samples_lights);
                } else {
                    ContinuationRandom draws{};
                    if (path_continues) draws = continuation_random<E>(random);
                    diffuse.push(surface, m, ray.direction, throughput, draws.direction.first, draws.direction.second,
                                 draws.choice_and_roulette.second, slot, elsewhere, samples_lights);
                    if (samples_lights)
                        for (uint32_t j = 0; j < shadow_ray_count; ++j)
                            diffuse.set_light_sample(diffuse.count - 1, j, light_sample_point<E>(scene, random, j));
                }
                if (diffuse.full()) shade_diffuse_chunk();
                continue;
            }
            if (vector_kernels && continues_as_specular(m, surface)) {  // the specular kernel's vertex
                if (!path_continues) continue;
                queue_camera_specular_vertex<E>(scene, m, surface, ray.direction, throughput, path, bounce, elsewhere, slot, specular);
                if (specular.full()) shade_specular_chunk();
                continue;
            }
        }
        if constexpr (kListedLights) {
            sample_listed_lights<E>(scene, m, surface, ray.direction, throughput, path, bounce,
                                    [&](const ShadowRay& shadow) { shadows.push(shadow, slot); });
        } else if (has_lights && gathers_direct_light(m)) {
            const DirectLightSampler<E> lights(scene, m, surface, light_sampling_point(surface, ray.direction),
                                               ray.direction, throughput, path, bounce, shadow_ray_count);
            lights.sample_all([&](const ShadowRay& shadow) { shadows.push(shadow, slot); });
        } else if (kRough && has_lights && m.is_microfacet()) {
            GlossyLightSampler<E>(scene, m, surface, ray.direction, throughput, path, bounce, shadow_ray_count)
                .sample_all([&](const ShadowRay& shadow) { shadows.push(shadow, slot); });
        }
        const auto next = continue_path<E, kRough>(scene, m, surface, ray.direction, throughput, path, bounce, elsewhere);
        if (next) {
            next_rays.push<E::mis>(*next, slot);
            if constexpr (kListedLights) {
                if (next->count_environment) next_rays.count_emission[next_rays.count - 1] |= RayQueue::kCountEnvironment;
                if (!scene.emitter_selection.empty()) paths.set_normal(slot, surface.normal);
            }
        }
    }
    if constexpr (!kListedLights) {
        shade_diffuse_chunk();
        if (specular.count > 0) shade_specular_chunk();
    }
}


// (Two macros, not one calling the other: E's commas would split it into more arguments.)
#define WT_SHADE_QUEUE_SIGNATURE(E, record_aovs, rough)                                                                   \
    void shade_queue<E, record_aovs, rough, false>(const Scene&, const ShadeKernels&, uint32_t, const RayQueue&,           \
                                                   const HitQueue&, PathTable&, ShadeChunks&, RayQueue&,           \
                                                   ShadowQueue&, const PhotonMaps*)
#define WT_SHADE_QUEUE_SIGNATURE_LIGHTS(E, record_aovs)                                                                   \
    void shade_queue<E, record_aovs, true, true>(const Scene&, const ShadeKernels&, uint32_t, const RayQueue&,             \
                                                 const HitQueue&, PathTable&, ShadeChunks&, RayQueue&,             \
                                                 ShadowQueue&, const PhotonMaps*)

}  // namespace wt
