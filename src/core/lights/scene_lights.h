#pragma once
// The scene file's "lights" list (environment, point, spot, directional) as the renderer samples
// it, together with the area lights: one distribution picks which light a light sample goes to,
// in proportion to each light's power (luminance), and the area lights as one entry (their
// LightTable then picks a triangle by area). Power: an area light pi A L, a point light 4 pi I,
// a spot 2 pi I (1 - (cos_inner + cos_outer) / 2), a directional light E pi r^2 and the
// environment pi r^2 times its radiance integrated over the sphere, r the radius of the scene's
// bounding sphere (pbrt-v4's Light::Phi: the infinite lights' power on the disk that covers the scene).
//
// Built only when the list is not empty, or the emissive triangles are picked by power or the
// light tree (then with the area lights as its one entry): a scene with area lights alone and
// selection by area keeps LightTable's sampling and the code paths it had (Scene::listed_lights).

#include <cstdint>
#include <optional>
#include <vector>

#include <glm/vec3.hpp>

#include "core/geometry/geometry_soa.h"
#include "core/lights/environment_light.h"
#include "core/lights/light_emission.h"
#include "core/lights/piecewise_constant.h"
#include "core/lights/punctual_light.h"
#include "core/description/scene_description.h"

namespace wt {

class LightTable;

class SceneLights {
public:
    SceneLights() = default;
    // `area_power`: the area lights' total (0 without any); `bounds`: a sphere that holds the scene.
    SceneLights(const std::vector<LightDescription>& lights, double area_power, const BoundingSphere& bounds);

    bool empty() const { return entries_.empty(); }
    // What the selection gives the area lights (LightTable::set_selection_probability), or 0.
    float area_probability() const { return area_probability_; }
    const std::optional<EnvironmentLight>& environment() const { return environment_; }
    float environment_probability() const { return environment_probability_; }
    const std::vector<PunctualLight>& punctual() const { return punctual_; }
    std::size_t bytes() const {
        return entries_.capacity() * sizeof(int) + selection_.bytes() + (environment_ ? environment_->bytes() : 0) +
               punctual_.capacity() * sizeof(PunctualLight);
    }
    float punctual_probability(std::size_t i) const { return selection_.probability(first_punctual_ + i); }
    // Some light a ray that leaves the scene can see (the environment, a directional light with an angle).
    bool seen_by_escaping_rays() const { return seen_by_escaping_rays_; }

    // Which light u picks: -1 the area lights, -2 the environment, else a punctual light's index.
    // `rescaled` is u within the pick, uniform in [0, 1), for the area lights' own choice.
    // Light paths start at the light it picks too (kernels/caustics/light_path.cpp).
    int pick(float u, float& rescaled) const;
    // The probability pick() gives `which` (as it returns it).
    float probability(int which) const {
        return which == -1 ? area_probability_ : which == -2 ? environment_probability_ : punctual_probability(std::size_t(which));
    }
    // The sphere the lights at infinity shine on and their power is measured on.
    const BoundingSphere& bounds() const { return bounds_; }

private:
    std::vector<int> entries_;  // per selection entry, as pick() returns
    DiscreteDistribution selection_;
    std::size_t first_punctual_ = 0;
    float area_probability_ = 0.0f;
    std::optional<EnvironmentLight> environment_;
    float environment_probability_ = 0.0f;
    std::vector<PunctualLight> punctual_;
    bool seen_by_escaping_rays_ = false;
    BoundingSphere bounds_;
};

// Sum over the emissive triangles of pi * area * luminance(emission), an emission texture's
// mean included (LightTable::mean_radiance): the area lights' power.
double area_light_power(const TriangleSoA& triangles, const LightTable& table);

}  // namespace wt
