#pragma once
// What happens at one path vertex — emission, light samples, the next direction, Russian
// roulette — written once and called by both the reference integrator and the wavefront shade
// kernel. The two integrators differ only in how they schedule this work, never in the
// estimator, so agreement between them tests the scheduling. Everything is a template over
// the Estimator (core/path/estimator.h): the sampler, nee or mis, and the indirect clamp.

#include <cmath>
#include <optional>

#include <glm/geometric.hpp>

#include "core/path/estimator.h"
#include "core/materials/bsdf.h"
#include "core/base/float_minmax.h"
#include "core/base/ray_offset.h"
#include "core/sampling/samplers.h"
#include "core/scene/scene.h"
#include "core/materials/shading_normal_bsdf.h"

namespace wt {

template <typename E>
inline PathSeed path_seed(const Scene& scene, uint32_t pixel, uint32_t sample) {
    return {E::Sampler::key_of(scene.settings.seed, pixel, sample), sample};
}

// The camera ray of the path's sample in pixel `pixel` (row-major index), placed about the
// pixel by the sampler and the pixel filter (core/camera/pixel_filter.h), and on the lens for a
// thin lens: the pinhole draws no lens sample. `weight` multiplies the path's radiance before it
// reaches the film: the filter's sample weight, 1 but for a filter with negative lobes.
struct CameraRay {
    Ray ray;
    float weight;
};

template <typename E>
inline CameraRay camera_ray(const Scene& scene, uint32_t pixel, const PathSeed& path) {
    const uint32_t width = uint32_t(scene.settings.width);
    const typename E::Sampler random(path, 0, uint32_t(scene.settings.shadow_rays));
    const PixelFilter::Sample filtered = scene.pixel_filter.sample(random.pixel_offset(scene.settings.seed, pixel, path.sample));
    const float x = float(pixel % width) + filtered.offset.x, y = float(pixel / width) + filtered.offset.y;
    if (!scene.camera.has_lens()) return {scene.camera.generate_ray(x, y), filtered.weight};
    return {scene.camera.generate_ray(x, y, E::Sampler::lens_position(path, scene.settings.seed, pixel)), filtered.weight};
}

// Radiance emitted towards the incoming ray: lights are one-sided, emitting on the side their
// geometric normal faces.
inline glm::vec3 emitted_towards(const Material& m, const glm::vec3& n_geom, const glm::vec3& d) {
    return glm::dot(d, n_geom) < 0.0f ? m.emission : glm::vec3(0.0f);
}

// Whether a vertex with this material samples the lights: diffuse and not black (an emitter
// with albedo 0, like the hexroom's light, reflects nothing, so its shadow rays would be wasted).
inline bool gathers_direct_light(const Material& m) {
    return !m.is_specular() && (m.albedo.x > 0.0f || m.albedo.y > 0.0f || m.albedo.z > 0.0f);
}

struct ShadowRay {
    Ray ray;
    float tmax;              // distance to (just short of) the light point
    glm::vec3 contribution;  // added to the path's radiance if nothing blocks the ray
};

// Aims `s` from `origin` (already moved off the shading surface) at the light point, itself
// moved off its surface, so neither the shading point's nor the light's own triangle can block
// the ray.
inline void aim_shadow_ray(ShadowRay& s, const glm::vec3& origin, const LightSample& light) {
    s.ray.origin = origin;
    const glm::vec3 target = offset_ray_origin(light.position, light.error, light.normal);
    const glm::vec3 span = target - origin;
    s.tmax = glm::length(span);
    s.ray.direction = span / s.tmax;
}

// The per-channel limit of each of a vertex's `count` light samples: the indirect clamp shared
// among them, or none (direct light and estimators without the clamp).
template <typename E>
inline float light_sample_clamp_limit(const Scene& scene, uint32_t bounce, uint32_t count) {
    return E::clamps_indirect && is_indirect_light_sample(bounce) ? scene.settings.estimator.clamp_indirect / float(count)
                                                                  : INFINITY;
}

// What every light sample at one diffuse vertex shares, computed once per vertex.
struct LightSamplingPoint {
    glm::vec3 normal;          // geometric, facing the incoming ray
    glm::vec3 shading_normal;  // turned to the same side; `normal` itself when flat
    glm::vec3 ray_origin;      // the shading point moved off its surface on that side
    bool smooth;               // SurfacePoint::smooth
};

inline LightSamplingPoint light_sampling_point(const SurfacePoint& surface, const glm::vec3& d) {
    const glm::vec3 n = glm::dot(d, surface.normal) < 0.0f ? surface.normal : -surface.normal;
    return {n, surface.smooth ? shading_normal_facing(surface.shading_normal, n) : n,
            offset_ray_origin(surface.position, surface.error, n), surface.smooth};
}

// The BSDF a diffuse vertex applies to light that arrives as power, seen from the view the BSDF
// was made for (light tracing's camera connections, the photons): f about the shading normal,
// times the adjoint correction cos_shading / cos_geometric for the geometric cosine the power
// already carries (folded_diffuse's K, which is f cos_shading, over cos_i; flat, plain f).
// `cos_i` is the geometric cosine of wi about at.normal, positive.
inline glm::vec3 diffuse_bsdf_for_power(const DiffuseBsdfAtView& bsdf, const LightSamplingPoint& at, const glm::vec3& wi,
                                        float cos_i) {
    return at.smooth ? folded_diffuse(bsdf, at.normal, at.shading_normal, wi, cos_i) / cos_i : bsdf(wi, cos_i);
}

// The emission a path adds at a hit, arriving along `ray` with `throughput` after a flight of
// `t`. `bsdf_pdf` is the solid-angle pdf with which the previous vertex's BSDF sampled `ray`
// when light samples there could have found this point too (mis only: 0 after the camera and
// after specular bounces, where no light sample competes and the emission counts in full).
// `kRough`: the scene may have rough materials (Scene::has_rough_materials); without them and
// without mis no pdf is ever passed, and the test is compiled out. `kListedLights`: the scene
// runs the listed lights' samplers (core/path/listed_light_sampler.h), whose emitter may have
// been picked by power or the light tree: then the pdf is that of triangle `prim` (the hit's)
// from the ray's origin and `previous_normal`, the previous vertex's geometric normal, which
// its light samples were picked for.
template <typename E, bool kRough = true, bool kListedLights = false>
inline glm::vec3 emission_added(const Scene& scene, const Material& m, const SurfacePoint& surface, const Ray& ray, float t,
                                const glm::vec3& throughput, float bsdf_pdf, uint32_t bounce, uint32_t prim = 0,
                                const glm::vec3& previous_normal = glm::vec3(0.0f)) {
    glm::vec3 e = throughput * emitted_towards(m, surface.normal, ray.direction);
    // (Without mis only a rough bounce passes a pdf: GlossyLightSampler weights its light samples.)
    if constexpr (E::mis || kRough) {
        if (bsdf_pdf > 0.0f && m.is_emissive()) {
            // The light samples' pdf for this point, per unit solid angle at the previous vertex.
            const float cos_light = -glm::dot(surface.normal, ray.direction);
            float pdf_area = scene.lights.pdf_area();
            if constexpr (kListedLights)
                if (!scene.emitter_selection.empty())
                    pdf_area = scene.emitter_selection.pdf_area(ray.origin, previous_normal, prim);
            const float light_pdf = pdf_area * t * t / cos_light;
            e *= power_heuristic(bsdf_pdf, float(scene.settings.shadow_rays) * light_pdf);
        }
    }
    if constexpr (E::clamps_indirect)
        if (is_indirect_emission(bounce)) e = clamped_per_channel(e, scene.settings.estimator.clamp_indirect);
    return e;
}

// The solid-angle pdf with which continue_path drew the diffuse direction wi at `surface`,
// arriving along d: cosine-weighted about the facing normal, or folded about the shading normal.
inline float diffuse_direction_pdf(const SurfacePoint& surface, const glm::vec3& d, const glm::vec3& wi) {
    const glm::vec3 n = glm::dot(d, surface.normal) < 0.0f ? surface.normal : -surface.normal;
    const float cos_geom = glm::dot(n, wi);
    if (!surface.smooth) return cos_geom * kInvPi;
    return folded_cosine_pdf(n, shading_normal_facing(surface.shading_normal, n), wi, cos_geom);
}

// The point on the area lights that light sample `index` of a vertex aims at, drawn from the
// vertex's random numbers (`random`, made for its path and bounce). With one emitter the choice
// is not read, and a sampler whose draws are not cheap skips it. (The SIMD shade stage draws
// its light samples with this too: kernels/shading.)
template <typename E>
[[gnu::always_inline]] inline LightSample light_sample_point(const Scene& scene, const typename E::Sampler& random,
                                                             uint32_t index) {
    const uint32_t base = dim::light_first + dim::per_shadow_ray * index;
    const UniformPair point = random.pair(base + dim::light_u);
    float choice = 0.0f;
    if (E::Sampler::kCheapDraws || scene.lights.size() > 1) choice = random(base + dim::light_choice);
    return scene.lights.sample(scene.triangles, choice, point.first, point.second);
}

// The light samples of one diffuse vertex (next-event estimation). Sample `index` of `count`
// estimates f * Le * cos_x * cos_y / (dist^2 * pdf_area), averaged over the `count` shadow rays;
// with mis, weighted by the power heuristic against the BSDF sampling of the same direction
// (when the path can still continue: at the bounce cap no BSDF sample competes). What the
// samples share (the ray origin, the BSDF's view-dependent part, where the vertex's random
// numbers start) is computed once, in the constructor, not once per shadow ray.
template <typename E = DefaultEstimator>
class DirectLightSampler {
public:
    DirectLightSampler(const Scene& scene, const Material& m, const SurfacePoint& surface, const LightSamplingPoint& at,
                       const glm::vec3& d, const glm::vec3& throughput, const PathSeed& path, uint32_t bounce, uint32_t count)
        : scene_(scene),
          at_(at),
          position_(surface.position),
          throughput_(throughput),
          bsdf_(m, at.shading_normal, -d),
          random_(path, bounce, count),
          count_(count),
          count_float_(float(count)),
          bsdf_competes_(E::mis && int(bounce) + 1 < scene.settings.max_bounces),
          clamp_limit_(light_sample_clamp_limit<E>(scene, bounce, count)) {}

    // Every light sample of the vertex, in index order; emit(const ShadowRay&) gets each one that
    // can contribute. One loop here rather than one call per sample in the caller: the shared
    // state stays in registers across the samples. Flat or folded BSDF is chosen once, here.
    // (Not an out-of-line call for the folded loop: this object's address would escape into it,
    // and g++ then reloads the shared state around every flat sample too.)
    template <typename Emit>
    void sample_all(Emit&& emit) const {
        ShadowRay s;
        if (at_.smooth) {
            for (uint32_t j = 0; j < count_; ++j)
                if (sample<true>(j, s)) emit(s);
            return;
        }
        for (uint32_t j = 0; j < count_; ++j)
            if (sample<false>(j, s)) emit(s);
    }

    // Writes light sample `index` to `s`; false, leaving `s` unspecified, when the sample cannot
    // contribute (light seen from behind, point below the geometric surface), so no ray is traced
    // for it. `Folded`: the vertex has a shading normal, and the BSDF is folded_diffuse()'s K.
    // (An out-parameter, not std::optional: the 40-byte copy out of it was 4 % of the sample.)
    // Always inlined: g++ judges it too big, and as a call it spills and reloads the shared
    // state around every sample.
    template <bool Folded>
    [[gnu::always_inline]] bool sample(uint32_t index, ShadowRay& s) const {
        const LightSample light = light_sample_point<E>(scene_, random_, index);
        const glm::vec3& n = at_.normal;
        const glm::vec3 to_light = light.position - position_;
        const float dist2 = glm::dot(to_light, to_light);
        if (!(dist2 > 0.0f)) return false;
        const float dist = std::sqrt(dist2);
        const glm::vec3 wi = to_light / dist;
        const float cos_x = glm::dot(n, wi);
        const float cos_y = -glm::dot(light.normal, wi);
        if (cos_x <= 0.0f || cos_y <= 0.0f) return false;

        // Folded, K stands for f * cos_x: its cosines are about the shading normal.
        const glm::vec3 f = Folded ? folded_diffuse(bsdf_, n, at_.shading_normal, wi, cos_x) : bsdf_(wi, cos_x);
        const float cosine_x = Folded ? 1.0f : cos_x;
        const float geometry = cosine_x * cos_y / (dist2 * light.pdf_area * count_float_);
        aim_shadow_ray(s, at_.ray_origin, light);
        s.contribution = throughput_ * f * light.radiance * geometry;
        if constexpr (E::mis) {
            if (bsdf_competes_) {
                const float light_pdf = light.pdf_area * dist2 / cos_y;  // per unit solid angle
                const float bsdf_pdf = Folded ? folded_cosine_pdf(n, at_.shading_normal, wi, cos_x) : cos_x * kInvPi;
                s.contribution *= power_heuristic(count_float_ * light_pdf, bsdf_pdf);
            }
        }
        if constexpr (E::clamps_indirect) s.contribution = clamped_per_channel(s.contribution, clamp_limit_);
        return true;
    }

private:
    const Scene& scene_;
    LightSamplingPoint at_;
    glm::vec3 position_;  // the shading point, before the offset
    glm::vec3 throughput_;
    DiffuseBsdfAtView bsdf_;  // about the shading normal
    typename E::Sampler random_;
    uint32_t count_;
    float count_float_;
    bool bsdf_competes_;  // mis, and the path may continue past this vertex
    float clamp_limit_;   // per shadow ray; infinite when this vertex's samples are not clamped
};

// With light tracing of caustics (Scene::light_traces_caustics, kernels/caustics), the light paths
// estimate every path whose first vertex from the camera is diffuse and whose last bounce before
// the light is a mirror or glass (camera -> diffuse -> anything -> specular -> light: caustics
// seen directly, and the light they throw on to other surfaces), and the camera paths leave
// exactly those out: the path space is split in two and each part has one estimator. With
// photons (Scene::merges_photons, kernels/photons/photon_gather.h) a path whose first hit is a
// mirror or glass gathers the same light paths as photons at its first diffuse vertex, and
// leaves the paths that end specular -> light from there on to them as well.
//
// A rough vertex R (rough conductor or glass) is on the camera paths' side of both splits: a
// light path ends at R if R is its first bounce (so R -> light is the camera paths', by R's
// light samples and, with mis, its BSDF samples), and never connects R to the camera nor leaves
// a photon there; so a camera path keeps everything through R, and R sets no
// specular_light_elsewhere. Each path still falls in exactly one part: with "diffuse" read as
// the diffuse materials only and "specular" as mirror, glass and smooth conductor, the rules
// above decide by the same three questions, and R answers "no" to both, so a path whose first
// hit is R, or whose last bounce is R, is the camera paths' alone, and light paths through R
// elsewhere (light -> specular -> ... R ... -> diffuse) are counted only by the light paths,
// whose camera paths see that diffuse vertex first (or gather there) and drop them.
struct PathContinuation {
    Ray ray;
    glm::vec3 throughput;
    // The next hit's emission is counted: always with mis, else only after a specular bounce
    // (no light sample covered this direction); never where the light paths count it.
    bool count_emission;
    // Light tracing only (never set without it): what a specular bounce of the path finds from
    // here on is the light paths' to count. Set when the first hit was diffuse (light tracing's
    // splats) and, with photons, at the first diffuse vertex after mirrors and glass (where the
    // photons were gathered, gathers_photons): so a path at bounce > 0 without it has met only
    // specular surfaces.
    bool specular_light_elsewhere;
    float bsdf_pdf;  // mis, or a rough bounce: the direction's pdf if light samples competed for it, else 0 (emission_added)
    // A scene with a "lights" list only (core/path/listed_light_sampler.h): the next ray, if it
    // leaves the scene, counts what it sees there (the environment, a directional light with an
    // angle). The same rule as count_emission: light paths start at those lights too.
    bool count_environment = false;
};

// Whether the photons' estimate is added at this vertex: the first diffuse vertex, past the
// first hit, of a path that has met only mirrors and glass before it, on a surface that reflects
// light, and early enough that a photon (two light path vertices at least) keeps the whole path
// within max_bounces (kernels/photons/photon_gather.h). `specular_light_elsewhere` is the
// incoming ray's.
inline bool gathers_photons(const Scene& scene, const Material& m, uint32_t bounce, bool specular_light_elsewhere) {
    return scene.merges_photons && bounce > 0 && !specular_light_elsewhere && int(bounce) + 2 < scene.settings.max_bounces &&
           gathers_direct_light(m);
}

// The most light path vertices a photon gathered at `bounce` may have: the path it completes
// has bounce + vertex surfaces, fewer than max_bounces, as the camera paths' own (whose last
// surface before the light is at bounce max_bounces - 1 at most).
inline uint32_t photon_vertex_limit(const Scene& scene, uint32_t bounce) {
    return uint32_t(scene.settings.max_bounces) - 1 - bounce;
}

// The random numbers continue_path draws at a vertex: the direction's pair, then the glass's
// reflect-or-refract choice and Russian roulette's. (The SIMD shade stage draws them with this
// too, for the vertices whose continuation its kernel computes: kernels/shading.)
struct ContinuationRandom {
    UniformPair direction, choice_and_roulette;
};
template <typename E>
inline ContinuationRandom continuation_random(const typename E::Sampler& random) {
    return {random.pair(dim::bsdf_u), random.pair(dim::bsdf_choice)};
}
template <typename E>
inline ContinuationRandom continuation_random(const Scene& scene, const PathSeed& path, uint32_t bounce) {
    return continuation_random<E>(typename E::Sampler(path, bounce, uint32_t(scene.settings.shadow_rays)));
}

// Samples the next direction from the BSDF and applies Russian roulette. Empty when the path
// ends. `bounce` is the index of the vertex being shaded (0 = first hit);
// `specular_light_elsewhere` is the incoming ray's (PathContinuation::specular_light_elsewhere).
// `kRough` as for emission_added: without it no sample is glossy.
template <typename E, bool kRough = true>
inline std::optional<PathContinuation> continue_path(const Scene& scene, const Material& m, const SurfacePoint& surface,
                                                     const glm::vec3& d, const glm::vec3& throughput, const PathSeed& path,
                                                     uint32_t bounce, bool specular_light_elsewhere) {
    if (int(bounce) + 1 >= scene.settings.max_bounces) return std::nullopt;
    const auto [direction, choice_and_roulette] = continuation_random<E>(scene, path, bounce);
    const FresnelModel fresnel = scene.settings.accuracy.fresnel;
    const BsdfSample s = surface.smooth ? sample_bsdf_about_shading_normal(m, surface.normal, surface.shading_normal, d,
                                                                           direction.first, direction.second,
                                                                           choice_and_roulette.first, fresnel)
                                        : sample_bsdf(m, surface.normal, d, direction.first, direction.second,
                                                      choice_and_roulette.first, fresnel);
    if (!s.valid) return std::nullopt;
    PathContinuation next;
    next.throughput = throughput * s.weight;
    // A black surface (the light's back, an albedo-0 emitter) ends the path: nothing it could
    // gather would count.
    if (!(next.throughput.x > 0.0f || next.throughput.y > 0.0f || next.throughput.z > 0.0f)) return std::nullopt;
    // Only a diffuse vertex hands the paths ending specular -> light on: light tracing connects
    // those to the camera and photons land on those. A rough vertex (s.glossy) is neither, so
    // the camera path keeps every path through it (see PathContinuation).
    const bool glossy = kRough && s.glossy;
    next.specular_light_elsewhere = specular_light_elsewhere || (!s.specular && !glossy &&
                                                                 (bounce == 0 ? scene.light_traces_caustics : scene.merges_photons));
    // A rough lobe is always weighted against its light samples, nee or mis: light samples alone
    // cannot find a sharp lobe's light, nor BSDF samples alone a small light (GlossyLightSampler).
    next.count_emission = (E::mis || s.specular || glossy) && !(next.specular_light_elsewhere && s.specular);
    next.count_environment = next.count_emission;
    next.bsdf_pdf = 0.0f;
    if constexpr (E::mis) {
        if (!s.specular) next.bsdf_pdf = glossy ? s.pdf : diffuse_direction_pdf(surface, d, s.direction);
    } else if (glossy) {
        next.bsdf_pdf = s.pdf;
    }
    if (int(bounce) >= scene.settings.rr_start_bounce) {
        // Survival proportional to throughput keeps the estimator unbiased (weight / q) while
        // ending dim paths early; the cap keeps even bright paths terminating.
        const float q = fmin_float(0.95f, fmax_float(next.throughput.x, fmax_float(next.throughput.y, next.throughput.z)));
        if (!(choice_and_roulette.second < q)) return std::nullopt;
        next.throughput /= q;
    }
    const glm::vec3 side = glm::dot(s.direction, surface.normal) > 0.0f ? surface.normal : -surface.normal;
    next.ray.origin = offset_ray_origin(surface.position, surface.error, side);
    next.ray.direction = s.direction;
    return next;
}

}  // namespace wt
