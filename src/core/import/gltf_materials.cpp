#include "core/import/gltf_materials.h"

#include <cmath>

#include <glm/common.hpp>

#include "core/import/material_mapping.h"
#include "core/materials/microfacet_material.h"

namespace wt {
namespace {

// The number `key` of extension `extension`, or `fallback`.
double extension_number(const tinygltf::Material& m, const char* extension, const char* key, double fallback) {
    const auto it = m.extensions.find(extension);
    if (it == m.extensions.end() || !it->second.Has(key)) return fallback;
    const tinygltf::Value& v = it->second.Get(key);
    return v.IsNumber() ? v.GetNumberAsDouble() : fallback;
}

glm::vec3 rgb(const std::vector<double>& factor, float fallback) {
    if (factor.size() < 3) return glm::vec3(fallback);
    return {float(factor[0]), float(factor[1]), float(factor[2])};
}

// glTF 2.0, 3.9.4: alphaMode OPAQUE ignores alpha; MASK cuts out where alpha (baseColorFactor's
// fourth component times the base colour texture's alpha) is below alphaCutoff (default 0.5);
// BLEND is rendered as stochastic transparency (core/scene/alpha_test.h). The alpha is the base
// colour texture's: where the material has no colour for that texture (glass) it is not read.
void map_alpha(const tinygltf::Material& m, const std::string& name, const std::string& path, ImportedMaterial& out) {
    const std::string where = path + ": material \"" + name + "\": ";
    if (m.alphaMode == "OPAQUE") return;
    if (m.alphaMode == "MASK") out.material.alpha_mode = AlphaMode::mask;
    else if (m.alphaMode == "BLEND") out.material.alpha_mode = AlphaMode::blend;
    else throw MeshFileError(where + "alphaMode \"" + m.alphaMode + "\" is not OPAQUE, MASK or BLEND");
    // JSON has no NaN, but a cutoff must be a number >= 0 (the specification's minimum).
    if (!(m.alphaCutoff >= 0.0) || !std::isfinite(m.alphaCutoff))
        throw MeshFileError(where + "alphaCutoff " + std::to_string(m.alphaCutoff) + " is not a number >= 0");
    out.material.alpha_cutoff = float(m.alphaCutoff);
    const std::vector<double>& factor = m.pbrMetallicRoughness.baseColorFactor;
    out.material.alpha_factor = factor.size() >= 4 ? fraction_from_file(factor[3], "baseColorFactor alpha", out) : 1.0f;
    // The light table samples an emitter's whole surface: its holes would emit.
    if (out.material.is_emissive())
        out.unmapped.push_back("alpha of an emitting material (it emits from its cut-out parts too)");
    out.material.alpha_texture = out.material.color_texture;
    if (out.material.alpha_texture < 0 && m.pbrMetallicRoughness.baseColorTexture.index >= 0)
        out.unmapped.push_back("baseColorTexture's alpha (no base colour on this material type)");
}

}  // namespace

ImportedMaterial map_gltf_material(const tinygltf::Material& m, const std::string& name, GltfTextures& textures) {
    ImportedMaterial out;
    const tinygltf::PbrMetallicRoughness& pbr = m.pbrMetallicRoughness;
    const glm::vec3 base = reflectance_from_file(rgb(pbr.baseColorFactor, 1.0f), "baseColorFactor", out);
    const float roughness = fraction_from_file(pbr.roughnessFactor, "roughnessFactor", out);
    const double ior_factor = extension_number(m, "KHR_materials_ior", "ior", 1.5);
    const float ior = ior_factor > 0.0 ? float(ior_factor) : 1.5f;
    const double strength = extension_number(m, "KHR_materials_emissive_strength", "emissiveStrength", 1.0);
    const glm::vec3 emission = rgb(m.emissiveFactor, 0.0f) * float(strength);
    const double transmission = extension_number(m, "KHR_materials_transmission", "transmissionFactor", 0.0);
    if (transmission > 0.0) {
        out.material.type = dielectric_type(roughness, ior);
        out.material.roughness = roughness;
        out.material.ior = ior;
        if (transmission < 1.0) out.unmapped.push_back("transmissionFactor < 1 (rendered as fully transmitting glass)");
        emission_from_file(emission, "emissiveFactor", out);
    } else {
        // A metallic-roughness texture varies metallic: such a material stays principled at
        // metallicFactor 1, metallic 1 times the texture.
        const float metallic = fraction_from_file(pbr.metallicFactor, "metallicFactor", out);
        out.material = principled_material(base, metallic, roughness, ior, glm::max(emission, glm::vec3(0.0f)),
                                           pbr.metallicRoughnessTexture.index >= 0);
    }
    out.material.name = m.name;
    const tinygltf::TextureInfo& mr_texture = pbr.metallicRoughnessTexture;
    const MaterialType type = out.material.type;
    // Each texture on TEXCOORD_0 or TEXCOORD_1 (its KHR_texture_transform included, whose texCoord
    // overrides the texture info's) where the material has the parameter it multiplies; otherwise a note.
    const auto map_texture = [&](const auto& info, bool applies, bool srgb, const std::string& field) {
        if (info.index < 0) return -1;
        if (!applies) {
            out.unmapped.push_back(field);
            return -1;
        }
        int set = info.texCoord;
        const auto transform = info.extensions.find("KHR_texture_transform");
        if (transform != info.extensions.end() && transform->second.Has("texCoord") && transform->second.Get("texCoord").IsNumber())
            set = transform->second.Get("texCoord").GetNumberAsInt();
        if (set != 0 && set != 1) {
            out.unmapped.push_back(field + " on TEXCOORD_" + std::to_string(set) + " (only TEXCOORD_0 and TEXCOORD_1 are read)");
            return -1;
        }
        return textures.add(info.index, info.extensions, srgb, name, field, set);
    };
    // The base colour texture multiplies the factor (glTF 2.0, 3.9.2): a principled material's
    // base colour, or the F0 of the conductor metallic 1 loads as; glass has no colour.
    const bool coloured = type == MaterialType::principled || type == MaterialType::conductor || type == MaterialType::rough_conductor;
    out.material.color_texture = map_texture(pbr.baseColorTexture, coloured, true, "baseColorTexture");
    out.material.metallic_roughness_texture =
        map_texture(mr_texture, type == MaterialType::principled, false, "metallicRoughnessTexture");
    // Normal maps perturb the shading normal, which every material type scatters about.
    out.material.normal_texture = map_texture(m.normalTexture, true, false, "normalTexture");
    out.material.normal_scale = std::isfinite(m.normalTexture.scale) ? float(m.normalTexture.scale) : 1.0f;
    map_texture(m.occlusionTexture, false, false, "occlusionTexture");
    // glTF 2.0 (3.9.5): the emissive texture (sRGB colour) multiplies emissiveFactor (and
    // KHR_materials_emissive_strength). With the factor 0, glTF's default, it changes nothing;
    // on a type that does not emit (glass, a metal) it is noted, as the factor is.
    if (emission.x > 0.0f || emission.y > 0.0f || emission.z > 0.0f)
        out.material.emission_texture = map_texture(m.emissiveTexture, out.material.is_emissive(), true, "emissiveTexture");
    map_alpha(m, name, textures.path(), out);
    return out;
}

}  // namespace wt
