#include <algorithm>

#include <cmath>

#include "core/materials/bsdf.h"
#include "core/scene_file/scene_schema.h"

// The materials section, and the lookup shapes use to name theirs.

namespace wt {
namespace {

constexpr const char* kMaterialTypes = "lambertian, oren_nayar, mirror, glass";

MaterialType read_material_type(const Reader& in, const Json& j, const std::string& path) {
    const std::string type = in.text(j, path);
    if (type == "lambertian") return MaterialType::lambertian;
    if (type == "oren_nayar") return MaterialType::oren_nayar;
    if (type == "mirror") return MaterialType::mirror;
    if (type == "glass") return MaterialType::glass;
    in.fail(path, std::string("unknown material type (allowed: ") + kMaterialTypes + "), got " + describe(j));
}

Material read_material(const Reader& in, const std::string& name, const Json& j, const std::string& path) {
    in.expect_object(j, path);
    if (!j.contains("type"))
        in.fail(member_path(path, "type"), std::string("required key is missing (one of ") + kMaterialTypes + ")");
    Material m;
    m.name = name;
    m.type = read_material_type(in, j.at("type"), member_path(path, "type"));
    const std::string type_name = j.at("type").get<std::string>();

    // The renderer only samples emission on diffuse surfaces; a glowing mirror would be ignored.
    if (m.is_specular() && j.contains("emission"))
        in.fail(member_path(path, "emission"), "emission is not supported on " + type_name +
                                                   " materials (only lambertian and oren_nayar can emit)");

    const std::string context = " for a " + type_name + " material";
    switch (m.type) {
    case MaterialType::lambertian: in.check_keys(j, path, {"type", "albedo", "emission"}, context); break;
    case MaterialType::oren_nayar: in.check_keys(j, path, {"type", "albedo", "sigma", "emission"}, context); break;
    case MaterialType::mirror: in.check_keys(j, path, {"type", "reflectance"}, context); break;
    case MaterialType::glass: in.check_keys(j, path, {"type", "ior"}, context); break;
    }

    if (m.type == MaterialType::lambertian || m.type == MaterialType::oren_nayar) {
        m.albedo = in.color(in.required(j, "albedo", path), member_path(path, "albedo"), true);
        if (const Json* e = in.optional(j, "emission")) m.emission = in.color(*e, member_path(path, "emission"), false);
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
    if (m.type == MaterialType::glass) {
        const Json& ior = in.required(j, "ior", path);
        m.ior = in.number(ior, member_path(path, "ior"));
        if (!(m.ior > 0.0f)) in.fail(member_path(path, "ior"), "must be positive, got " + describe(ior));
    }
    return m;
}


}  // namespace

std::vector<Material> read_materials(const Reader& in, const Json& j, const std::string& path) {
    in.expect_object(j, path);
    std::vector<Material> materials;
    for (const auto& member : j.items()) {
        if (member.key().empty()) in.fail(path, "material names must not be empty");
        materials.push_back(read_material(in, member.key(), member.value(), member_path(path, member.key())));
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
