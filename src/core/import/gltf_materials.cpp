#include "core/import/gltf_materials.h"

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

}  // namespace

ImportedMaterial map_gltf_material(const tinygltf::Material& m) {
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
        const float metallic = fraction_from_file(pbr.metallicFactor, "metallicFactor", out);
        out.material = principled_material(base, metallic, roughness, ior, glm::max(emission, glm::vec3(0.0f)));
    }
    out.material.name = m.name;
    if (m.alphaMode != "OPAQUE") out.unmapped.push_back("alphaMode " + m.alphaMode);

    const struct { int index; const char* name; } textures[] = {
        {pbr.baseColorTexture.index, "baseColorTexture"},
        {pbr.metallicRoughnessTexture.index, "metallicRoughnessTexture"},
        {m.normalTexture.index, "normalTexture"},
        {m.occlusionTexture.index, "occlusionTexture"},
        {m.emissiveTexture.index, "emissiveTexture"}};
    for (const auto& t : textures)
        if (t.index >= 0) out.unmapped.push_back(t.name);
    return out;
}

}  // namespace wt
