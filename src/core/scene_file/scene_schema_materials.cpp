#include <algorithm>

#include <cmath>

#include "core/materials/bsdf.h"
#include "core/materials/microfacet_material.h"
#include "core/scene_file/scene_schema.h"

// The materials section, and the lookup shapes use to name theirs.

namespace wt {
namespace {

constexpr const char* kMaterialTypes = "lambertian, oren_nayar, mirror, glass, conductor, rough_glass, principled";

// The type as the file names it; a conductor or rough_glass is resolved by its roughness later
// (microfacet_material.h), so these two come back as rough_conductor and rough_glass here, and a
// principled with metallic 1 may load as a conductor.
MaterialType read_material_type(const Reader& in, const Json& j, const std::string& path) {
    const std::string type = in.text(j, path);
    if (type == "lambertian") return MaterialType::lambertian;
    if (type == "oren_nayar") return MaterialType::oren_nayar;
    if (type == "mirror") return MaterialType::mirror;
    if (type == "glass") return MaterialType::glass;
    if (type == "conductor") return MaterialType::rough_conductor;
    if (type == "rough_glass") return MaterialType::rough_glass;
    if (type == "principled") return MaterialType::principled;
    in.fail(path, std::string("unknown material type (allowed: ") + kMaterialTypes + "), got " + describe(j));
}

float read_ior(const Reader& in, const Json& j, const std::string& path) {
    const Json& ior = in.required(j, "ior", path);
    const float value = in.number(ior, member_path(path, "ior"));
    if (!(value > 0.0f)) in.fail(member_path(path, "ior"), "must be positive, got " + describe(ior));
    return value;
}

// A factor in [0, 1], as the number `v` of member `key`.
float read_fraction(const Reader& in, const Json& v, const char* key, const std::string& path) {
    const float value = in.number(v, member_path(path, key));
    if (!(value >= 0.0f && value <= 1.0f)) in.fail(member_path(path, key), "must be in [0, 1], got " + describe(v));
    return value;
}

// Perceptual roughness, 0 (smooth) by default.
float read_roughness(const Reader& in, const Json& j, const std::string& path) {
    const Json* r = in.optional(j, "roughness");
    return r ? read_fraction(in, *r, "roughness", path) : 0.0f;
}

// glTF's metallic-roughness parameters, all three required (glTF's defaults, metallic 1 and
// roughness 1, are not what a scene file's author would guess); ior 1.5 and no emission by default.
Material read_principled(const Reader& in, const Json& j, const std::string& path, std::vector<TextureImage>& textures) {
    int32_t texture = -1;
    const glm::vec3 base_color =
        read_color_or_texture(in, in.required(j, "base_color", path), member_path(path, "base_color"), textures, texture);
    const float metallic = read_fraction(in, in.required(j, "metallic", path), "metallic", path);
    const float roughness = read_fraction(in, in.required(j, "roughness", path), "roughness", path);
    const float ior = j.contains("ior") ? read_ior(in, j, path) : 1.5f;
    const Json* e = in.optional(j, "emission");
    int32_t emission_texture = -1;
    const glm::vec3 emission =
        e ? read_color_or_texture(in, *e, member_path(path, "emission"), textures, emission_texture, false) : glm::vec3(0.0f);
    Material m = principled_material(base_color, metallic, roughness, ior, emission);
    m.color_texture = texture;
    if (m.is_emissive()) m.emission_texture = emission_texture;
    return m;
}

// A conductor's Fresnel term: f0 (Schlick; white if nothing is given) or a complex index
// eta + i k, both or neither.
void read_conductor_fresnel(const Reader& in, const Json& j, const std::string& path, Material& m) {
    const Json* eta = in.optional(j, "eta");
    const Json* k = in.optional(j, "k");
    if (const Json* f0 = in.optional(j, "f0")) {
        if (eta || k)
            in.fail(member_path(path, eta ? "eta" : "k"), "give either f0 or the complex index eta and k, not both");
        m.f0 = in.color(*f0, member_path(path, "f0"), true);
        return;
    }
    if (!eta && !k) return;
    if (!eta || !k) in.fail(member_path(path, eta ? "k" : "eta"), "required key is missing (eta and k come together)");
    m.eta = in.color(*eta, member_path(path, "eta"), false);
    m.k = in.color(*k, member_path(path, "k"), false);
    for (int c = 0; c < 3; ++c)
        if (!(m.eta[c] > 0.0f)) in.fail(element_path(member_path(path, "eta"), std::size_t(c)), "must be positive, got " + describe((*eta)[std::size_t(c)]));
}

Material read_material(const Reader& in, const std::string& name, const Json& j, const std::string& path,
                       std::vector<TextureImage>& textures) {
    in.expect_object(j, path);
    if (!j.contains("type"))
        in.fail(member_path(path, "type"), std::string("required key is missing (one of ") + kMaterialTypes + ")");
    Material m;
    m.name = name;
    m.type = read_material_type(in, j.at("type"), member_path(path, "type"));
    const std::string type_name = j.at("type").get<std::string>();

    // The renderer only samples emission on diffuse surfaces; a glowing mirror would be ignored.
    if ((m.is_specular() || m.is_microfacet()) && m.type != MaterialType::principled && j.contains("emission"))
        in.fail(member_path(path, "emission"), "emission is not supported on " + type_name +
                                                   " materials (only lambertian, oren_nayar and principled can emit)");

    const std::string context = " for a " + type_name + " material";
    switch (m.type) {
    case MaterialType::lambertian: in.check_keys(j, path, {"type", "albedo", "emission"}, context); break;
    case MaterialType::oren_nayar: in.check_keys(j, path, {"type", "albedo", "sigma", "emission"}, context); break;
    case MaterialType::mirror: in.check_keys(j, path, {"type", "reflectance"}, context); break;
    case MaterialType::glass: in.check_keys(j, path, {"type", "ior"}, context); break;
    case MaterialType::conductor:
    case MaterialType::rough_conductor: in.check_keys(j, path, {"type", "f0", "eta", "k", "roughness"}, context); break;
    case MaterialType::rough_glass: in.check_keys(j, path, {"type", "ior", "roughness"}, context); break;
    case MaterialType::principled:
        in.check_keys(j, path, {"type", "base_color", "metallic", "roughness", "ior", "emission"}, context);
        break;
    }
    if (m.type == MaterialType::principled) {
        const std::string name_kept = m.name;
        m = read_principled(in, j, path, textures);
        m.name = name_kept;
        return m;
    }

    if (m.type == MaterialType::lambertian || m.type == MaterialType::oren_nayar) {
        m.albedo = read_color_or_texture(in, in.required(j, "albedo", path), member_path(path, "albedo"), textures, m.color_texture);
        if (const Json* e = in.optional(j, "emission"))
            m.emission = read_color_or_texture(in, *e, member_path(path, "emission"), textures, m.emission_texture, false);
        if (!m.is_emissive()) m.emission_texture = -1;  // 0 times the texture is 0
    }
    if (m.type == MaterialType::oren_nayar) {
        const Json& sigma = in.required(j, "sigma", path);
        m.sigma = in.number(sigma, member_path(path, "sigma"));
        if (!(m.sigma >= 0.0f)) in.fail(member_path(path, "sigma"), "must be non-negative, got " + describe(sigma));
        // sigma^2 overflows a float past about 1.8e19, and the coefficients become inf/inf.
        const OrenNayarTerms terms = oren_nayar_terms(m.sigma);
        if (!std::isfinite(terms.a) || !std::isfinite(terms.b))
            in.fail(member_path(path, "sigma"), "is too large for the Oren-Nayar coefficients in 32-bit float "
                                                "(sigma^2 overflows), got " + describe(sigma));
    }
    if (m.type == MaterialType::mirror) {
        if (const Json* r = in.optional(j, "reflectance"))
            m.reflectance = in.color(*r, member_path(path, "reflectance"), true);
    }
    if (m.type == MaterialType::glass) m.ior = read_ior(in, j, path);
    if (m.type == MaterialType::rough_conductor) {
        read_conductor_fresnel(in, j, path, m);
        m.roughness = read_roughness(in, j, path);
        m.type = conductor_type(m.roughness);
    }
    if (m.type == MaterialType::rough_glass) {
        m.ior = read_ior(in, j, path);
        m.roughness = read_roughness(in, j, path);
        m.type = dielectric_type(m.roughness, m.ior);
    }
    return m;
}


}  // namespace

std::vector<Material> read_materials(const Reader& in, const Json& j, const std::string& path,
                                     std::vector<TextureImage>& textures) {
    in.expect_object(j, path);
    std::vector<Material> materials;
    for (const auto& member : j.items()) {
        if (member.key().empty()) in.fail(path, "material names must not be empty");
        materials.push_back(read_material(in, member.key(), member.value(), member_path(path, member.key()), textures));
    }
    return materials;
}

uint32_t find_material(const Reader& in, const std::vector<Material>& materials, MaterialNames& names,
                       const Json& j, const std::string& path) {
    const std::string name = in.text(j, path);
    if (const std::optional<uint32_t> index = names.find(name)) return *index;
    // A message of readable length, whatever the number of materials.
    constexpr std::size_t kListed = 20;
    std::vector<std::string> listed;
    for (std::size_t i = 0; i < std::min(materials.size(), kListed); ++i) listed.push_back(materials[i].name);
    if (materials.size() > kListed) listed.push_back("... " + std::to_string(materials.size()) + " in all");
    in.fail(path, "no material named " + Json(name).dump() + " (defined: " +
                      (listed.empty() ? std::string("none") : join(listed)) + ")");
}

}  // namespace wt
