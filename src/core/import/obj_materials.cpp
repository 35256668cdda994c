#include "core/import/obj_materials.h"

#include <optional>
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

// map_d's -imfchan: r, g, b and l name the channel; tinyobjloader writes m (matte) where the
// file names none, which is read_coverage_texture_file's automatic choice.
std::optional<CoverageChannel> coverage_channel(char imfchan) {
    switch (imfchan) {
        case 'm': return CoverageChannel::automatic;
        case 'r': return CoverageChannel::red;
        case 'g': return CoverageChannel::green;
        case 'b': return CoverageChannel::blue;
        case 'l': return CoverageChannel::luminance;
        default: return std::nullopt;  // z (depth) has no meaning for coverage
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
        std::optional<CoverageChannel> channel = coverage_channel(m.alpha_texopt.imfchan);
        if (!channel) {
            out.unmapped.push_back(std::string("map_d -imfchan ") + m.alpha_texopt.imfchan + " (its default channel read)");
            channel = CoverageChannel::automatic;
        }
        try {
            out.material.alpha_texture = textures.add_coverage(m.alpha_texname, *channel);
        } catch (const ImageError& e) {
            throw MeshFileError(obj_path + ": material \"" + m.name + "\": map_d: " + e.what());
        }
    } else if (out.material.alpha_factor == 0.0f) {
        // Followed, as Blender and Cycles follow it, but said: exporters that write Tr where they
        // mean d (some write Tr 1 for opaque) make whole objects vanish this way.
        out.unmapped.push_back("d 0: the material is invisible (an opaque one is d 1; Tr is 1 - d)");
    }
    if (out.material.is_emissive()) out.unmapped.push_back("dissolve of an emitting material (it emits from its transparent parts too)");
}

}  // namespace

int ObjTextures::add_color(const std::string& file) { return add(file, std::nullopt); }
int ObjTextures::add_coverage(const std::string& file, CoverageChannel channel) { return add(file, channel); }

int ObjTextures::add(const std::string& file, Use use) {
    if (!read_) return -1;
    const std::filesystem::path relative(file);
    const std::string resolved = relative.is_absolute() ? file : (base_dir_ / relative).string();
    if (const auto it = index_of_.find({resolved, use}); it != index_of_.end()) return it->second;
    TextureImage image;
    image.name = resolved;
    if (!use) {
        image.srgb = colour_file_is_srgb(resolved);
        image.texels = read_texture_file(resolved);
    } else {
        image.srgb = false;  // coverage is data (and the alpha test reads alpha, never decoded)
        image.texels = read_coverage_texture_file(resolved, *use);
    }
    out_.push_back(std::move(image));
    return index_of_[{resolved, use}] = int(out_.size() - 1);
}

ImportedMaterial map_obj_material(const tinyobj::material_t& m, const std::string& obj_path, ObjTextures& textures) {
    ImportedMaterial out;
    const glm::vec3 kd(m.diffuse[0], m.diffuse[1], m.diffuse[2]);
    const glm::vec3 ks(m.specular[0], m.specular[1], m.specular[2]);
    const glm::vec3 ke = glm::max(glm::vec3(m.emission[0], m.emission[1], m.emission[2]), glm::vec3(0.0f));
    // tinyobjloader leaves Pr and Pm at 0 when a file has neither, so "Pr 0 Pm 0" reads as no PBR keys.
    const bool pbr = m.roughness != 0.0f || m.metallic != 0.0f;
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
        const glm::vec3 base = reflectance_from_file(kd, "Kd", out);
        const float metallic = pbr ? fraction_from_file(m.metallic, "Pm", out) : 0.0f;
        const float roughness = pbr ? fraction_from_file(m.roughness, "Pr", out) : roughness_from_phong_exponent(m.shininess);
        if (!pbr) out.unmapped.push_back("Ks (the specular is a dielectric's, F0 0.04; Ns gave its roughness)");
        out.material = principled_material(base, metallic, roughness, 1.5f, ke);
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
    if (maps_kd) {
        try {
            out.material.color_texture = textures.add_color(m.diffuse_texname);
        } catch (const ImageError& e) {
            throw MeshFileError(obj_path + ": material \"" + m.name + "\": map_Kd: " + e.what());
        }
    }

    const struct { std::string name; const char* key; } unread[] = {
        {m.ambient_texname, "map_Ka"},   {maps_kd ? std::string() : m.diffuse_texname, "map_Kd"},     {m.specular_texname, "map_Ks"},
        {m.specular_highlight_texname, "map_Ns"}, {m.bump_texname, "bump"}, {m.displacement_texname, "disp"},
        {m.reflection_texname, "refl"},    {m.roughness_texname, "map_Pr"},
        {m.metallic_texname, "map_Pm"},  {m.sheen_texname, "map_Ps"},       {m.emissive_texname, "map_Ke"},
        {m.normal_texname, "norm"}};
    for (const auto& t : unread)
        if (!t.name.empty()) out.unmapped.push_back(std::string(t.key) + " texture");
    map_dissolve(m, obj_path, textures, out);
    return out;
}

}  // namespace wt
