#pragma once
// Light samples and escaped rays in a scene with a "lights" list (Scene::listed_lights): the
// counterparts of DirectLightSampler, GlossyLightSampler and emission_added (path_vertex.h,
// glossy_light_sampler.h) when a light sample may go to the area lights, the environment or a
// punctual light, picked by power (core/lights/scene_lights.h), and whose area light may be
// picked by power or the light tree (Scene::emitter_selection). A scene with neither never runs
// this code: its vertices run today's samplers, on today's bits.
//
// Which strategy counts what, so each estimator stays unbiased (as for the area lights):
// - Point and spot lights and a directional light of angle 0 are deltas: only light samples
//   find them, always in full.
// - The environment and a directional light with an angle are found by light samples and by
//   rays that leave the scene (escaped_radiance). Seen from the camera or after a mirror or
//   glass, an escaped ray counts in full (no light sample competes there). After a diffuse
//   bounce it counts with mis, weighted by the power heuristic against the light samples; with
//   nee not at all, the light samples having covered it. After a rough bounce it is weighted,
//   nee or mis, as the rough vertex's light samples are (GlossyLightSampler).
// - With light tracing, light paths start at every light (kernels/caustics, picked by power as
//   here), so the paths the camera paths leave to them (PathContinuation::specular_light_elsewhere)
//   are left whichever light they end at: an escaped ray after such a specular bounce is the
//   light paths' (PathContinuation::count_environment), and the delta lights, which no camera
//   path reaches through a mirror or glass, have their caustics from the light paths alone.

#include <cmath>

#include <glm/geometric.hpp>

#include "core/path/estimator.h"
#include "core/path/glossy_light_sampler.h"
#include "core/lights/scene_lights.h"
#include "core/path/path_vertex.h"
#include "core/scene/scene.h"

namespace wt {

// One light sample as the shading point sees it.
struct IncidentLight {
    glm::vec3 wi;      // towards the light, unit
    glm::vec3 weight;  // what f cos multiplies: radiance (or intensity / dist^2, or irradiance) over the pdf
    float pdf;         // per unit solid angle, the selection included; 0 for a delta light
    enum class Target : uint8_t { area, point, infinite } target;
    LightSample area;  // Target::area: the light point, for aim_shadow_ray
    glm::vec3 point;   // Target::point: the light's position
};

// Light sample (u_choice, u0, u1) of the scene's lights from `position`; false if it cannot
// contribute (an area light seen from behind, outside a spot's cone, a zero pdf). An emitter
// picked by power or the light tree (Scene::emitter_selection) is picked for `selection_point`,
// the vertex's shading point moved off its surface (as the origin of the BSDF-sampled ray whose
// emission emission_added weighs with the same pdf), and the vertex's geometric normal.
inline bool sample_incident_light(const Scene& scene, const glm::vec3& position, const glm::vec3& selection_point,
                                  const glm::vec3& normal, float u_choice, float u0, float u1, IncidentLight& out) {
    const SceneLights& lights = scene.listed_lights;
    float rescaled = 0.0f;
    const int which = lights.pick(u_choice, rescaled);
    if (which == -1) {
        LightSample light;  // its pdf includes the selection
        if (scene.emitter_selection.empty()) light = scene.lights.sample(scene.triangles, rescaled, u0, u1);
        else if (!scene.emitter_selection.sample(scene.lights, selection_point, normal, rescaled, u0, u1, light)) return false;
        const glm::vec3 to_light = light.position - position;
        const float dist2 = glm::dot(to_light, to_light);
        if (!(dist2 > 0.0f)) return false;
        out.wi = to_light / std::sqrt(dist2);
        const float cos_y = -glm::dot(light.normal, out.wi);
        if (cos_y <= 0.0f) return false;
        out.weight = light.radiance * (cos_y / (dist2 * light.pdf_area));
        out.pdf = light.pdf_area * dist2 / cos_y;
        out.target = IncidentLight::Target::area;
        out.area = light;
        return true;
    }
    if (which == -2) {
        const EnvironmentSample e = lights.environment()->sample(u0, u1);
        out.pdf = lights.environment_probability() * e.pdf;
        if (!(out.pdf > 0.0f)) return false;
        out.wi = e.direction;
        out.weight = e.radiance / out.pdf;
        out.target = IncidentLight::Target::infinite;
        return true;
    }
    const PunctualLight& p = lights.punctual()[std::size_t(which)];
    const float probability = lights.punctual_probability(std::size_t(which));
    if (p.type == LightType::directional) {
        out.target = IncidentLight::Target::infinite;
        if (!p.is_area_at_infinity()) {
            out.wi = -p.axis;
            out.weight = p.irradiance / probability;
            out.pdf = 0.0f;
            return true;
        }
        out.wi = p.sample_cone(u0, u1);
        out.pdf = probability * p.cone_pdf();
        out.weight = p.radiance / out.pdf;
        return true;
    }
    const glm::vec3 to_light = p.position - position;
    const float dist2 = glm::dot(to_light, to_light);
    if (!(dist2 > 0.0f)) return false;
    out.wi = to_light / std::sqrt(dist2);
    const glm::vec3 intensity = p.type == LightType::spot ? p.spot_intensity(-out.wi) : p.intensity;
    if (!(intensity.x > 0.0f || intensity.y > 0.0f || intensity.z > 0.0f)) return false;
    out.weight = intensity / (dist2 * probability);
    out.pdf = 0.0f;
    out.target = IncidentLight::Target::point;
    out.point = p.position;
    return true;
}

// The shadow ray from `origin` (moved off the shading surface) to the light sample: to the area
// light's point moved off its surface, to the punctual light's position, or out of the scene.
inline void aim_incident_shadow_ray(ShadowRay& s, const glm::vec3& origin, const IncidentLight& light) {
    if (light.target == IncidentLight::Target::area) return aim_shadow_ray(s, origin, light.area);
    s.ray.origin = origin;
    if (light.target == IncidentLight::Target::infinite) {
        s.ray.direction = light.wi;
        s.tmax = INFINITY;
        return;
    }
    const glm::vec3 span = light.point - origin;
    s.tmax = glm::length(span);
    s.ray.direction = span / s.tmax;
}

// The light samples of one vertex, diffuse or rough (`Vertex`: DiffuseListedVertex or
// GlossyListedVertex below), in index order, with the random dimensions DirectLightSampler uses.
template <typename E, typename Vertex>
class ListedLightSampler {
public:
    ListedLightSampler(const Scene& scene, const Vertex& vertex, const SurfacePoint& surface, const glm::vec3& throughput,
                       const PathSeed& path, uint32_t bounce, uint32_t count)
        : scene_(scene),
          vertex_(vertex),
          position_(surface.position),
          normal_(surface.normal),
          throughput_(throughput),
          random_(path, bounce, count),
          count_(count),
          count_float_(float(count)),
          bsdf_competes_((E::mis || Vertex::kAlwaysWeighs) && int(bounce) + 1 < scene.settings.max_bounces),
          clamp_limit_(light_sample_clamp_limit<E>(scene, bounce, count)) {}

    template <typename Emit>
    void sample_all(Emit&& emit) const {
        ShadowRay s;
        for (uint32_t j = 0; j < count_; ++j)
            if (sample(j, s)) emit(s);
    }

    bool sample(uint32_t index, ShadowRay& s) const {
        const uint32_t base = dim::light_first + dim::per_shadow_ray * index;
        const UniformPair point = random_.pair(base + dim::light_u);
        IncidentLight light;
        if (!sample_incident_light(scene_, position_, vertex_.selection_point(), normal_, random_(base + dim::light_choice),
                                   point.first, point.second, light))
            return false;
        glm::vec3 f_cos;
        float bsdf_pdf = 0.0f;
        glm::vec3 origin;
        if (!vertex_.evaluate(light.wi, f_cos, bsdf_pdf, origin)) return false;
        aim_incident_shadow_ray(s, origin, light);
        s.contribution = throughput_ * f_cos * light.weight / count_float_;
        if (bsdf_competes_ && light.pdf > 0.0f) s.contribution *= power_heuristic(count_float_ * light.pdf, bsdf_pdf);
        if constexpr (E::clamps_indirect) s.contribution = clamped_per_channel(s.contribution, clamp_limit_);
        return true;
    }

private:
    const Scene& scene_;
    const Vertex& vertex_;
    glm::vec3 position_;
    glm::vec3 normal_;  // geometric, as the shading point's BSDF-sampled ray carries it (emission_added)
    glm::vec3 throughput_;
    typename E::Sampler random_;
    uint32_t count_;
    float count_float_;
    bool bsdf_competes_;
    float clamp_limit_;
};

// A diffuse vertex: f cos about the shading normal (folded where the vertex is smooth) and the
// cosine-weighted pdf continue_path samples it with; weighed against its BSDF with mis only.
struct DiffuseListedVertex {
    static constexpr bool kAlwaysWeighs = false;
    LightSamplingPoint at;
    DiffuseBsdfAtView bsdf;

    DiffuseListedVertex(const Material& m, const LightSamplingPoint& point, const glm::vec3& d)
        : at(point), bsdf(m, point.shading_normal, -d) {}

    bool evaluate(const glm::vec3& wi, glm::vec3& f_cos, float& pdf, glm::vec3& origin) const {
        const float cos_x = glm::dot(at.normal, wi);
        if (cos_x <= 0.0f) return false;
        if (at.smooth) {
            f_cos = folded_diffuse(bsdf, at.normal, at.shading_normal, wi, cos_x);
            pdf = folded_cosine_pdf(at.normal, at.shading_normal, wi, cos_x);
        } else {
            f_cos = bsdf(wi, cos_x) * cos_x;
            pdf = cos_x * kInvPi;
        }
        origin = at.ray_origin;
        return true;
    }
    // The origin of this vertex's BSDF-sampled ray (continue_path moves it off the same side).
    const glm::vec3& selection_point() const { return at.ray_origin; }
};

// A rough vertex: the microfacet BSDF, towards both sides for rough glass; always weighed
// against its BSDF (GlossyLightSampler's rule).
struct GlossyListedVertex {
    static constexpr bool kAlwaysWeighs = true;
    glm::vec3 normal;  // geometric, facing the incoming ray
    glm::vec3 origin_front, origin_behind;
    MicrofacetBsdfAtView bsdf;

    GlossyListedVertex(const Scene& scene, const Material& m, const SurfacePoint& surface, const glm::vec3& d)
        : normal(glm::dot(d, surface.normal) < 0.0f ? surface.normal : -surface.normal),
          origin_front(offset_ray_origin(surface.position, surface.error, normal)),
          origin_behind(offset_ray_origin(surface.position, surface.error, -normal)),
          bsdf(m, microfacet_normal(normal, surface.smooth ? &surface.shading_normal : nullptr, d), normal,
               glm::dot(d, surface.normal) < 0.0f, -d, scene.settings.accuracy.fresnel) {}

    bool evaluate(const glm::vec3& wi, glm::vec3& f_cos, float& pdf, glm::vec3& origin) const {
        const float cos_x = glm::dot(normal, wi);
        if (cos_x == 0.0f || (cos_x < 0.0f && !bsdf.transmits())) return false;
        f_cos = bsdf.f_cos(wi);
        if (!(f_cos.x > 0.0f || f_cos.y > 0.0f || f_cos.z > 0.0f)) return false;
        pdf = bsdf.pdf(wi);
        origin = cos_x > 0.0f ? origin_front : origin_behind;
        return true;
    }
    // The origin of a reflected BSDF-sampled ray. A transmitted one starts from origin_behind, a
    // rounding error's width away: its emission's pdf is asked from there, and may differ from
    // the one the light sample used in the last bits.
    const glm::vec3& selection_point() const { return origin_front; }
};

// Every light sample of the vertex (diffuse or rough; none elsewhere), to emit(const ShadowRay&).
template <typename E, typename Emit>
inline void sample_listed_lights(const Scene& scene, const Material& m, const SurfacePoint& surface, const glm::vec3& d,
                                 const glm::vec3& throughput, const PathSeed& path, uint32_t bounce, Emit&& emit) {
    const uint32_t count = uint32_t(scene.settings.shadow_rays);
    if (gathers_direct_light(m)) {
        const DiffuseListedVertex vertex(m, light_sampling_point(surface, d), d);
        ListedLightSampler<E, DiffuseListedVertex>(scene, vertex, surface, throughput, path, bounce, count)
            .sample_all(emit);
    } else if (m.is_microfacet()) {
        const GlossyListedVertex vertex(scene, m, surface, d);
        ListedLightSampler<E, GlossyListedVertex>(scene, vertex, surface, throughput, path, bounce, count)
            .sample_all(emit);
    }
}

// What a ray travelling along d that leaves the scene adds, arriving with `throughput`:
// the environment and the directional lights with an angle, each weighted against its light
// samples where `bsdf_pdf` > 0 (as emission_added). `bounce` is the vertex the ray would have hit.
template <typename E>
inline glm::vec3 escaped_radiance(const Scene& scene, const glm::vec3& d, const glm::vec3& throughput, float bsdf_pdf,
                                  uint32_t bounce) {
    const SceneLights& lights = scene.listed_lights;
    const float count = float(scene.settings.shadow_rays);
    glm::vec3 sum(0.0f);
    if (lights.environment()) {
        glm::vec3 le = lights.environment()->radiance(d);
        if (bsdf_pdf > 0.0f)
            le *= power_heuristic(bsdf_pdf, count * lights.environment_probability() * lights.environment()->pdf(d));
        sum += le;
    }
    for (std::size_t i = 0; i < lights.punctual().size(); ++i) {
        const PunctualLight& p = lights.punctual()[i];
        glm::vec3 le = p.radiance_along(d);
        if (!(le.x > 0.0f || le.y > 0.0f || le.z > 0.0f)) continue;
        if (bsdf_pdf > 0.0f) le *= power_heuristic(bsdf_pdf, count * lights.punctual_probability(i) * p.cone_pdf());
        sum += le;
    }
    glm::vec3 e = throughput * sum;
    if constexpr (E::clamps_indirect)
        if (is_indirect_emission(bounce)) e = clamped_per_channel(e, scene.settings.estimator.clamp_indirect);
    return e;
}

}  // namespace wt
