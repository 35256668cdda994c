#include "core/import/obj_materials.h"

#include <sstream>

#include <cmath>

#include <glm/common.hpp>

#include "core/import/material_mapping.h"
#include "core/materials/microfacet_material.h"
#include "core/image_io/image_error.h"
#include "core/system/regular_file.h"
#include "core/textures/texture_file.h"

namespace wt {

std::string read_mtl_file(const std::string& path, std::vector<tinyobj::material_t>& materials,
                          std::map<std::string, int>& ids) {
    std::istringstream text;
    try {
        text.str(read_regular_file(path, kMaxSceneFileBytes));
    } catch (const InputFileError& e) {
        return e.what();
    }
    std::string warn, err;  // tinyobjloader's warnings are about values it chose between
    tinyobj::LoadMtl(&ids, &materials, &text, &warn, &err);
    return "";
}

namespace {

// Phong's exponent Ns to perceptual roughness as Blender's OBJ importer converts it,
// 1 - sqrt(Ns / 1000) with Ns clamped to [0, 1000]: the inverse of what Blender's exporter
// writes (Ns = 1000 (1 - roughness)^2), so a material exported from Blender comes back with its
// roughness, and renders as Cycles renders the same file through Blender's importer.
float roughness_from_phong_exponent(float ns) {
    const float clamped = ns >= 0.0f ? (ns <= 1000.0f ? ns : 1000.0f) : 0.0f;
    return 1.0f - std::sqrt(clamped / 1000.0f);
}

// A map's -imfchan: r, g, b and l name the channel; tinyobjloader writes m (matte) where the
// file names none, which reads `unnamed`. z (depth) means nothing for these maps: a note, and
// `unnamed` too.
ScalarMap scalar_map(const std::string& file, const tinyobj::texture_option_t& options, const char* key, ScalarChannel unnamed,
                     ImportedMaterial& out) {
    ScalarMap map{file, unnamed};
    switch (options.imfchan) {
        case 'r': map.channel = ScalarChannel::red; break;
        case 'g': map.channel = ScalarChannel::green; break;
        case 'b': map.channel = ScalarChannel::blue; break;
        case 'l': map.channel = ScalarChannel::luminance; break;
        case 'm': break;
        default: out.unmapped.push_back(std::string(key) + " -imfchan " + options.imfchan + " (its default channel read)");
    }
    return map;
}

// Reads a map through `read`, an ImageError becoming a MeshFileError naming the OBJ file, the
// material and the map's key.
template <class Read>
int read_map(const tinyobj::material_t& m, const std::string& obj_path, const char* key, Read read) {
    try {
        return read();
    } catch (const ImageError& e) {
        throw MeshFileError(obj_path + ": material \"" + m.name + "\": " + key + ": " + e.what());
    }
}

// MTL's dissolve as alpha: d times map_d's coverage (the specification multiplies them),
// rendered as glTF's BLEND is, stochastic transparency (core/scene/alpha_test.h). That is how
// Blender's importer sets such a material up (blend mode BLEND, map_d into the BSDF's alpha), so
// Cycles renders the same file the same way: the leaves and chains of Sponza-like scenes come
// out cut, and a d 0.3 window lets 70 % of the light through. A refracting material (illum 4, 6,
// 7) is transparent by its own glass; there d is the exporter's note of that, not a cut-out.
void map_dissolve(const tinyobj::material_t& m, const std::string& obj_path, ObjTextures& textures, ImportedMaterial& out) {
    const bool has_map = !m.alpha_texname.empty();
    // A NaN d (tinyobjloader's parser makes none) reads as 1, since it is not below 1.
    const bool partial = m.dissolve < 1.0f;
    if (!partial && !has_map) return;
    if (out.material.type == MaterialType::glass || out.material.type == MaterialType::rough_glass) {
        out.unmapped.push_back(std::string(has_map ? "map_d" : "d (dissolve)") + " on a refracting material (illum 4, 6 or 7: its glass is its transparency)");
        return;
    }
    out.material.alpha_mode = AlphaMode::blend;
    out.material.alpha_factor = partial ? fraction_from_file(m.dissolve, "d", out) : 1.0f;
    if (has_map) {
        const ScalarMap map = scalar_map(m.alpha_texname, m.alpha_texopt, "map_d", ScalarChannel::alpha_else_luminance, out);
        out.material.alpha_texture = read_map(m, obj_path, "map_d", [&] { return textures.add_coverage(map); });
    } else if (out.material.alpha_factor == 0.0f) {
        // Followed, as Blender and Cycles follow it, but said: exporters that write Tr where they
        // mean d (some write Tr 1 for opaque) make whole objects vanish this way.
        out.unmapped.push_back("d 0: the material is invisible (an opaque one is d 1; Tr is 1 - d)");
    }
    if (out.material.is_emissive()) out.unmapped.push_back("dissolve of an emitting material (it emits from its transparent parts too)");
}

}  // namespace

ImportedMaterial map_obj_material(const tinyobj::material_t& m, const std::string& obj_path, ObjTextures& textures) {
    ImportedMaterial out;
    const glm::vec3 kd(m.diffuse[0], m.diffuse[1], m.diffuse[2]);
    const glm::vec3 ks(m.specular[0], m.specular[1], m.specular[2]);
    // map_Ke replaces Ke, as map_Pr and map_Pm replace their values (below): its colour is the emission.
    const bool emission_map = !m.emissive_texname.empty();
    const glm::vec3 ke = emission_map ? glm::vec3(1.0f) : glm::max(glm::vec3(m.emission[0], m.emission[1], m.emission[2]), glm::vec3(0.0f));
    // tinyobjloader leaves Pr and Pm at 0 when a file has neither, so "Pr 0 Pm 0" reads as no PBR keys.
    const bool roughness_map = !m.roughness_texname.empty(), metallic_map = !m.metallic_texname.empty();
    const bool pbr = m.roughness != 0.0f || m.metallic != 0.0f || roughness_map || metallic_map;
    const bool highlight = m.illum != 0 && m.illum != 1 && (ks.x > 0.0f || ks.y > 0.0f || ks.z > 0.0f);
    if (m.illum == 3 || m.illum == 5) {
        out.material.type = MaterialType::mirror;
        out.material.reflectance = reflectance_from_file(ks, "Ks", out);
    } else if (m.illum == 4 || m.illum == 6 || m.illum == 7) {
        const float roughness = fraction_from_file(m.roughness, "Pr", out);
        float ior = 1.5f;
        if (m.ior > 0.0f) ior = m.ior;
        else out.unmapped.push_back("Ni " + std::to_string(m.ior) + " (not positive: ior 1.5 used)");
        out.material.type = dielectric_type(roughness, ior);
        out.material.roughness = roughness;
        out.material.ior = ior;
    } else if (pbr || highlight) {
        // The PBR extension's Pr and Pm where given, else Phong's highlight as a dielectric's
        // specular lobe of roughness from Ns; Ks's colour and strength have no place in glTF's
        // model (its dielectric reflects F0 0.04, from ior 1.5), so only its presence counts.
        // A map replaces its value, as Blender's importer links it in place of the value: the
        // factor it multiplies (glTF's layout) is 1. With a map the material stays principled,
        // as glTF's does with its metallicRoughnessTexture (the shade stage reads it there).
        const glm::vec3 base = reflectance_from_file(kd, "Kd", out);
        const float metallic = metallic_map ? 1.0f : (pbr ? fraction_from_file(m.metallic, "Pm", out) : 0.0f);
        const float roughness = roughness_map ? 1.0f
                                : pbr         ? fraction_from_file(m.roughness, "Pr", out)
                                              : roughness_from_phong_exponent(m.shininess);
        if (!pbr) out.unmapped.push_back("Ks (the specular is a dielectric's, F0 0.04; Ns gave its roughness)");
        out.material = principled_material(base, metallic, roughness, 1.5f, ke, roughness_map || metallic_map);
        if (roughness_map || metallic_map) {
            const ScalarMap r = roughness_map ? scalar_map(m.roughness_texname, m.roughness_texopt, "map_Pr", ScalarChannel::luminance, out) : ScalarMap{};
            const ScalarMap p = metallic_map ? scalar_map(m.metallic_texname, m.metallic_texopt, "map_Pm", ScalarChannel::luminance, out) : ScalarMap{};
            const char* key = roughness_map && metallic_map ? "map_Pr and map_Pm" : (roughness_map ? "map_Pr" : "map_Pm");
            out.material.metallic_roughness_texture = read_map(m, obj_path, key, [&] { return textures.add_metallic_roughness(r, p); });
        }
    } else {
        out.material.type = MaterialType::lambertian;
        out.material.albedo = reflectance_from_file(kd, "Kd", out);
    }
    out.material.name = m.name;
    emission_from_file(ke, "Ke", out);
    // map_Kd on the materials whose colour is Kd (Pm 1 loads as a conductor of F0 Kd); a mirror
    // or glass has none to multiply.
    const MaterialType type = out.material.type;
    const bool maps_kd = !m.diffuse_texname.empty() &&
                         (type == MaterialType::lambertian || type == MaterialType::principled ||
                          type == MaterialType::conductor || type == MaterialType::rough_conductor);
    if (maps_kd) out.material.color_texture = read_map(m, obj_path, "map_Kd", [&] { return textures.add_color(m.diffuse_texname); });
    // map_Ke where the material emits (a mirror, metal or glass cannot: emission_from_file noted it).
    const bool maps_ke = emission_map && out.material.is_emissive();
    if (maps_ke) out.material.emission_texture = read_map(m, obj_path, "map_Ke", [&] { return textures.add_color(m.emissive_texname); });
    // map_Pr and map_Pm where the principled material above read them; a mirror or glass has neither.
    const bool maps_pbr = type == MaterialType::principled;

    const struct { std::string name; const char* key; } unread[] = {
        {m.ambient_texname, "map_Ka"},   {maps_kd ? std::string() : m.diffuse_texname, "map_Kd"},     {m.specular_texname, "map_Ks"},
        {m.specular_highlight_texname, "map_Ns"}, {m.bump_texname, "bump"}, {m.displacement_texname, "disp"},
        {m.reflection_texname, "refl"},    {maps_pbr ? std::string() : m.roughness_texname, "map_Pr"},
        {maps_pbr ? std::string() : m.metallic_texname, "map_Pm"},  {m.sheen_texname, "map_Ps"},       {maps_ke ? std::string() : m.emissive_texname, "map_Ke"},
        {m.normal_texname, "norm"}};
    for (const auto& t : unread)
        if (!t.name.empty()) out.unmapped.push_back(std::string(t.key) + " texture");
    map_dissolve(m, obj_path, textures, out);
    return out;
}

}  // namespace wt
