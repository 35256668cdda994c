#include "kernels/caustics/light_path.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "core/base/float_minmax.h"
#include "core/lights/light_emission.h"
#include "core/scene/material_at_hit.h"
#include "core/materials/bsdf.h"
#include "core/materials/shading_normal_bsdf.h"
#include "core/path/path_vertex.h"
#include "core/base/ray_offset.h"
#include "core/sampling/rng.h"
#include "core/sampling/sampling.h"
#include "kernels/isa/bvh_single_ray.h"
#include "kernels/accel/scene_intersect.h"

namespace wt {

namespace {

constexpr uint64_t kLightPathSalt = 0x11647a7c5ULL;  // keeps light paths' keys apart from the camera paths'

// The random dimensions of a light path: at its start (bounce 0) the point, the direction and
// the emitter; at each surface vertex k (bounce k) the direction, the glass's reflect-or-refract
// choice and Russian roulette.
namespace light_dim {
constexpr uint32_t point_u = 0;      // with point_v
constexpr uint32_t direction_u = 2;  // with direction_v
constexpr uint32_t emitter = 4;
constexpr uint32_t specular_choice = 4;
constexpr uint32_t roulette = 5;
constexpr uint32_t lens_u = 6;        // the camera connection's point on a thin lens, with lens_v
constexpr uint32_t splat_pixel_x = 8; // the splat's pixel under a filter wider than its pixel, with _y
}  // namespace light_dim

// Veach's correction for shading normals on paths traced from the lights (thesis, sec. 5.3.2;
// pbrt-v4's CorrectShadingNormal): the adjoint of scattering about a shading normal ns is not the
// scattering itself. `toward_previous` points back along the arriving path, `next` along the
// sampled direction; 1 on flat surfaces, where ns is the geometric normal.
float shading_normal_adjoint(const SurfacePoint& s, const glm::vec3& toward_previous, const glm::vec3& next) {
    const float denominator = std::abs(glm::dot(toward_previous, s.normal)) * std::abs(glm::dot(next, s.shading_normal));
    if (!(denominator > 0.0f)) return 0.0f;
    return std::abs(glm::dot(toward_previous, s.shading_normal)) * std::abs(glm::dot(next, s.normal)) / denominator;
}

}  // namespace

uint64_t light_path_key(uint64_t seed, uint64_t index, uint32_t sample) {
    return mix64(mix64(mix64(seed ^ kLightPathSalt) + index * kGoldenGamma) + uint64_t(sample) * kGoldenGamma);
}

uint64_t light_paths_per_sample(const RenderSettings& s) {
    const double paths = double(s.estimator.light_paths_per_pixel) * double(s.width) * double(s.height);
    return std::max<uint64_t>(1, uint64_t(std::llround(paths)));
}

LightPathTracer::LightPathTracer(const Scene& scene, const BvhView* bvh, bool records_photons)
    : scene_(scene),
      bvh_(bvh),
      records_photons_(records_photons),
      starts_at_area_lights_only_(scene.listed_lights.empty()),
      inverse_path_count_(float(1.0 / double(light_paths_per_sample(scene.settings)))),
      specular_targets_(SpecularTargets::of(scene)) {}

Hit LightPathTracer::closest(const Ray& ray) const {
    return bvh_ ? bvh_intersect_closest(*bvh_, scene_.settings.accuracy, ray) : intersect_closest(scene_, ray);
}

bool LightPathTracer::blocked(const Ray& ray, float tmax) const {
    return bvh_ ? bvh_intersect_any(*bvh_, scene_.settings.accuracy, ray, tmax) : intersect_any(scene_, ray, tmax);
}

namespace {

// The ray leaving area light point `light` cosine-weighted about its normal, `power` as
// AreaLightStart's.
[[gnu::always_inline]] inline std::optional<LightRay> area_light_ray(const LightSample& light, const glm::vec3& power,
                                                                     const UniformPair& direction) {
    LightRay r;
    r.ray.direction = glm::normalize(Frame(light.normal).to_world(sample_cosine_hemisphere(direction.first, direction.second)));
    if (!(glm::dot(r.ray.direction, light.normal) > 0.0f)) return std::nullopt;  // lost to rounding at the horizon
    r.ray.origin = offset_ray_origin(light.position, light.error, light.normal);
    r.power = power;
    r.weight = glm::vec3(1.0f);
    return r;
}

glm::vec3 area_light_power(const LightSample& light, float pdf_area) { return light.radiance * (kPi / pdf_area); }

}  // namespace

AreaLightStart LightPathTracer::area_light_start(uint64_t key) const {
    const VertexRandom random(key, 0);
    const UniformPair point = random.pair(light_dim::point_u);
    const UniformPair direction = random.pair(light_dim::direction_u);
    const LightSample light = scene_.lights.sample(scene_.triangles, random(light_dim::emitter), point.first, point.second);
    // The area lights' pdf alone: without a "lights" list they are picked with probability one.
    return {light, area_light_power(light, scene_.lights.pdf_area_alone()), direction};
}

std::optional<LightRay> LightPathTracer::start(uint64_t key) const {
    const AreaLightStart s = area_light_start(key);
    return area_light_ray(s.light, s.power, s.direction);
}

std::optional<LightRay> LightPathTracer::start_at_listed_lights(uint64_t key) const {
    const VertexRandom random(key, 0);
    const UniformPair point = random.pair(light_dim::point_u);
    const UniformPair direction = random.pair(light_dim::direction_u);
    const SceneLights& lights = scene_.listed_lights;
    float rescaled = 0.0f;
    const int which = lights.pick(random(light_dim::emitter), rescaled);
    if (which == -1) {
        // The table's pdf includes the area lights' pick (LightTable::set_selection_probability).
        const LightSample light = scene_.lights.sample(scene_.triangles, rescaled, point.first, point.second);
        return area_light_ray(light, area_light_power(light, light.pdf_area), direction);
    }
    const EmittedRay e = which == -2 ? sample_emission(*lights.environment(), lights.bounds(), direction.first,
                                                       direction.second, point.first, point.second)
                                     : sample_emission(lights.punctual()[std::size_t(which)], lights.bounds(),
                                                       direction.first, direction.second, point.first, point.second);
    const float probability = lights.probability(which);
    if (!e.valid || !(probability > 0.0f)) return std::nullopt;
    // No surface to move off: a point or spot light is no geometry, an infinite light's disk is
    // outside the scene.
    return LightRay{{e.origin, e.direction}, e.power / probability, glm::vec3(1.0f)};
}

// `vertex` counts the surfaces the path has hit, this one included: a camera path that ends in
// this light path meets the light after as many vertices of its own.
LightVertex LightPathTracer::at_vertex(uint64_t key, uint32_t vertex, const LightRay& at, const Hit& hit,
                                       std::optional<Material>& textured) const {
    return at_vertex(key, vertex, at, hit, surface_at(scene_, at.ray, hit), textured);
}

// (`surface` by value: a normal map may change its shading normal.)
LightVertex LightPathTracer::at_vertex(uint64_t key, uint32_t vertex, const LightRay& at, const Hit& hit,
                                       SurfacePoint surface, std::optional<Material>& textured) const {
    const RenderSettings& settings = scene_.settings;
    const Ray& ray = at.ray;
    const Material& m = material_at(scene_, hit, surface, ray, false, textured);
    LightVertex out;
    if (!m.is_specular()) {
        // A diffuse first bounce is direct light: the camera paths' light samples estimate it.
        if (vertex == 1) return out;
        out.connection = connect_to_camera(surface, m, ray.direction, at.power * at.weight, VertexRandom(key, vertex));
        if (records_photons_) out.photon = photon_at(surface, m, vertex, ray.direction, at.power * at.weight);
    }
    // Camera paths shade no vertex from max_bounces on, so none could meet the light after more.
    if (int(vertex) + 1 >= settings.max_bounces) return out;
    const VertexRandom random(key, vertex);
    const UniformPair u = random.pair(light_dim::direction_u);
    const float u_choice = random(light_dim::specular_choice);  // (with roulette's, one pair: queue_specular)
    const BsdfSample s = surface.smooth ? sample_bsdf_about_shading_normal(m, surface.normal, surface.shading_normal,
                                                                           ray.direction, u.first, u.second, u_choice,
                                                                           settings.accuracy.fresnel)
                                        : sample_bsdf(m, surface.normal, ray.direction, u.first, u.second, u_choice,
                                                      settings.accuracy.fresnel);
    if (!s.valid) return out;
    glm::vec3 weight = at.weight * s.weight;
    if (surface.smooth) weight *= shading_normal_adjoint(surface, -ray.direction, s.direction);
    if (roulette_at(vertex)) {
        // As the camera paths' roulette: survival by the weight's largest channel, capped.
        const float q = fmin_float(0.95f, fmax_float(weight.x, fmax_float(weight.y, weight.z)));
        if (!(random(light_dim::roulette) < q)) return out;
        weight /= q;
    }
    if (!(weight.x > 0.0f || weight.y > 0.0f || weight.z > 0.0f)) return out;
    const glm::vec3 side = glm::dot(s.direction, surface.normal) > 0.0f ? surface.normal : -surface.normal;
    out.next = LightRay{{offset_ray_origin(surface.position, surface.error, side), s.direction}, at.power, weight};
    return out;
}

bool LightPathTracer::queue_specular(uint64_t key, uint32_t vertex, const LightRay& at, const SurfacePoint& surface,
                                     uint32_t slot, SpecularVertexQueue& q) const {
    const Material& m = scene_.materials[surface.material];
    if (!continues_as_specular(m, surface)) return false;
    if (int(vertex) + 1 >= scene_.settings.max_bounces) return false;  // at_vertex ends the path: nothing to queue
    static_assert(light_dim::roulette == light_dim::specular_choice + 1 && light_dim::specular_choice % 2 == 0,
                  "the choice and roulette are one pair");
    const UniformPair draws = VertexRandom(key, vertex).pair(light_dim::specular_choice);
    q.push(surface.position, surface.error, surface.normal, at.ray.direction, at.weight, m.type == MaterialType::glass,
           m.reflectance, m.ior, draws.first, draws.second, slot);
    return true;
}

void LightPathTracer::trace(uint64_t index, uint32_t sample, RayCounts& counts, std::vector<CameraSplat>& splats,
                            std::vector<LightPathVertexRecord>* record, PhotonList* photons) const {
    const uint64_t key = light_path_key(scene_.settings.seed, index, sample);
    std::optional<LightRay> ray = starts_at_area_lights_only_ ? start(key) : start_at_listed_lights(key);
    ++counts.light_paths;
    if (ray && !record && !first_ray_counts(ray->ray)) return;  // a record lists the vertex that ends it too
    std::optional<Material> textured;
    for (uint32_t vertex = 1; ray; ++vertex) {
        ++counts.light_rays;
        const Hit hit = closest(ray->ray);
        if (!hit.found()) return;
        const LightVertex v = at_vertex(key, vertex, *ray, hit, textured);
        bool was_blocked = false;
        if (v.connection) {
            ++counts.camera_connections;
            was_blocked = blocked(v.connection->ray, v.connection->tmax);
            if (!was_blocked) splats.push_back(v.connection->splat);
        }
        if (photons && v.photon) photons->push_back(*v.photon), ++counts.photons;
        if (record) {
            const SurfacePoint s = surface_at(scene_, ray->ray, hit);
            record->push_back({vertex, hit, s.material, s.position, ray->power * ray->weight,
                               v.connection ? std::optional<CameraSplat>(v.connection->splat) : std::nullopt, was_blocked});
        }
        ray = v.next;
    }
}

// The t = 1 connection: what the camera sees of the light arriving at `surface` along `arriving`
// with `power`. Per unit area of the surface the pixel receives radiance * cos_o / dist^2 *
// importance (Camera::film_point); light tracing's estimate of the radiance term is power * f,
// with f about the shading normal as the camera paths' light samples see it (folded_diffuse,
// divided by the geometric cosine the power already carries), which is also what the adjoint
// correction makes of it (pbrt-v4's BDPT connection to the camera).
std::optional<CameraConnection> LightPathTracer::connect_to_camera(const SurfacePoint& surface, const Material& m,
                                                                   const glm::vec3& arriving, const glm::vec3& power,
                                                                   const VertexRandom& random) const {
    if (!gathers_direct_light(m)) return std::nullopt;  // a black surface reflects nothing to see
    const Camera& camera = scene_.camera;
    const PixelFilter& filter = scene_.pixel_filter;
    // A thin lens: the connection goes to a point of the lens, drawn uniformly as the camera rays' are.
    glm::vec3 lens = camera.eye();
    std::optional<Camera::FilmPoint> film;
    if (camera.has_lens()) {
        const UniformPair u = random.pair(light_dim::lens_u);
        lens = camera.lens_point({u.first, u.second});
        film = camera.film_point_through_lens(surface.position, lens, filter.margin());
    } else {
        film = camera.film_point(surface.position, filter.margin());
    }
    if (!film) return std::nullopt;
    const glm::vec3 to_eye = lens - surface.position;
    const float dist2 = glm::dot(to_eye, to_eye);
    if (!(dist2 > 0.0f)) return std::nullopt;
    const glm::vec3 wo = to_eye / std::sqrt(dist2);
    const LightSamplingPoint at = light_sampling_point(surface, -wo);  // normals facing the eye
    const glm::vec3 wi = -arriving;
    const float cos_i = glm::dot(at.normal, wi), cos_o = glm::dot(at.normal, wo);
    if (!(cos_i > 0.0f && cos_o > 0.0f)) return std::nullopt;  // lit from behind, as the camera sees it
    const glm::vec3 f = diffuse_bsdf_for_power(DiffuseBsdfAtView(m, at.shading_normal, wo), at, wi, cos_i);

    const glm::vec3 span = lens - at.ray_origin;
    const float tmax = glm::length(span);
    const uint32_t width = uint32_t(scene_.settings.width);
    uint32_t pixel;
    float filter_weight = 1.0f;
    if (filter.is_unit_box()) {
        // film_point keeps x and y inside the image, so their floors are pixel coordinates.
        pixel = uint32_t(film->y) * width + uint32_t(film->x);
    } else {
        // A wider filter: the pixel by its weight among the pixels whose samples reach this point.
        const UniformPair u = random.pair(light_dim::splat_pixel_x);
        const PixelFilter::AxisChoice x = filter.choose_pixel(film->x, u.first), y = filter.choose_pixel(film->y, u.second);
        if (x.pixel < 0 || x.pixel >= int(width) || y.pixel < 0 || y.pixel >= scene_.settings.height) return std::nullopt;
        pixel = uint32_t(y.pixel) * width + uint32_t(x.pixel);
        filter_weight = x.weight * y.weight;
    }
    const float scale = cos_o / dist2 * film->importance * inverse_path_count_;
    return CameraConnection{{at.ray_origin, span / tmax}, tmax,
                            {pixel, power * f * (filter.is_unit_box() ? scale : scale * filter_weight)}};
}

// A photon for the camera paths that see this surface through a mirror or glass
// (kernels/photons): only where one could gather it, on a surface that reflects light, at a
// vertex from which a camera path of at least two vertices stays within max_bounces
// (photon_gather.h: j - 1 + vertex < max_bounces with j >= 2), and with a finite power.
std::optional<Photon> LightPathTracer::photon_at(const SurfacePoint& surface, const Material& m, uint32_t vertex,
                                                 const glm::vec3& arriving, const glm::vec3& power) const {
    if (!gathers_direct_light(m) || int(vertex) + 1 >= scene_.settings.max_bounces) return std::nullopt;
    const glm::vec3 p = power * inverse_path_count_;
    if (!(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z))) return std::nullopt;
    const glm::vec3 facing = glm::dot(arriving, surface.normal) < 0.0f ? surface.normal : -surface.normal;
    return Photon{surface.position, arriving, facing, p, vertex};
}

}  // namespace wt
