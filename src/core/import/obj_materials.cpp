#include "core/import/obj_materials.h"

#include <sstream>

#include "core/import/material_mapping.h"
#include "core/regular_file.h"

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

ImportedMaterial map_obj_material(const tinyobj::material_t& m) {
    ImportedMaterial out;
    Material& mat = out.material;
    mat.name = m.name;
    const glm::vec3 kd(m.diffuse[0], m.diffuse[1], m.diffuse[2]);
    const glm::vec3 ks(m.specular[0], m.specular[1], m.specular[2]);
    if (m.illum == 3 || m.illum == 5) {
        mat.type = MaterialType::mirror;
        mat.reflectance = reflectance_from_file(ks, "Ks", out);
    } else if (m.illum == 4 || m.illum == 6 || m.illum == 7) {
        mat.type = MaterialType::glass;
        if (m.ior > 0.0f) mat.ior = m.ior;
        else out.unmapped.push_back("Ni " + std::to_string(m.ior) + " (not positive: ior 1.5 used)");
    } else {
        mat.type = MaterialType::lambertian;
        mat.albedo = reflectance_from_file(kd, "Kd", out);
    }
    emission_from_file(glm::vec3(m.emission[0], m.emission[1], m.emission[2]), "Ke", out);

    const struct { const std::string& name; const char* key; } textures[] = {
        {m.ambient_texname, "map_Ka"},   {m.diffuse_texname, "map_Kd"},     {m.specular_texname, "map_Ks"},
        {m.specular_highlight_texname, "map_Ns"}, {m.bump_texname, "bump"}, {m.displacement_texname, "disp"},
        {m.alpha_texname, "map_d"},      {m.reflection_texname, "refl"},    {m.roughness_texname, "map_Pr"},
        {m.metallic_texname, "map_Pm"},  {m.sheen_texname, "map_Ps"},       {m.emissive_texname, "map_Ke"},
        {m.normal_texname, "norm"}};
    for (const auto& t : textures)
        if (!t.name.empty()) out.unmapped.push_back(std::string(t.key) + " texture");
    return out;
}

}  // namespace wt
