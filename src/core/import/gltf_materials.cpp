#include "core/import/gltf_materials.h"

#include "core/import/material_mapping.h"

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
    Material& mat = out.material;
    mat.name = m.name;
    const tinygltf::PbrMetallicRoughness& pbr = m.pbrMetallicRoughness;
    const glm::vec3 base = rgb(pbr.baseColorFactor, 1.0f);
    const double transmission = extension_number(m, "KHR_materials_transmission", "transmissionFactor", 0.0);
    if (transmission > 0.0) {
        mat.type = MaterialType::glass;
        const double ior = extension_number(m, "KHR_materials_ior", "ior", 1.5);
        if (ior > 0.0) mat.ior = float(ior);
        if (transmission < 1.0) out.unmapped.push_back("transmissionFactor < 1 (rendered as clear glass)");
    } else if (pbr.metallicFactor >= 1.0 && pbr.roughnessFactor <= 0.0) {
        mat.type = MaterialType::mirror;
        mat.reflectance = reflectance_from_file(base, "baseColorFactor", out);
    } else {
        mat.type = MaterialType::lambertian;
        mat.albedo = reflectance_from_file(base, "baseColorFactor", out);
        if (pbr.metallicFactor > 0.0) out.unmapped.push_back("metallicFactor > 0 (rendered as diffuse)");
    }
    const double strength = extension_number(m, "KHR_materials_emissive_strength", "emissiveStrength", 1.0);
    emission_from_file(rgb(m.emissiveFactor, 0.0f) * float(strength), "emissiveFactor", out);
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
