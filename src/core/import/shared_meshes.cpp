#include "core/import/shared_meshes.h"

#include <cstdint>

namespace wt {

std::vector<ImportedMesh> take_shared_meshes(ImportedMesh& mesh) {
    std::vector<ImportedMesh> shared(mesh.shared_count);
    if (mesh.shared_count == 0) return shared;
    // Index mesh.shared_count is what stays.
    const uint32_t kept = mesh.shared_count;
    std::vector<ImportedMesh*> target(mesh.shared_count + 1);
    ImportedMesh stays;
    for (uint32_t s = 0; s < mesh.shared_count; ++s) target[s] = &shared[s];
    target[kept] = &stays;
    std::vector<uint32_t> owner(mesh.positions.size(), kept), new_index(mesh.positions.size(), 0);
    for (const MeshPiece& piece : mesh.pieces) {
        const uint32_t to = piece.shared == MeshPiece::kNotShared ? kept : piece.shared;
        ImportedMesh& out = *target[to];
        MeshPiece moved = piece;
        moved.first_vertex = out.positions.size();
        out.pieces.push_back(moved);
        for (std::size_t v = piece.first_vertex; v < piece.first_vertex + piece.vertex_count; ++v) {
            owner[v] = to;
            new_index[v] = uint32_t(out.positions.size());
            out.positions.push_back(mesh.positions[v]);
            if (!mesh.normals.empty()) out.normals.push_back(mesh.normals[v]);
            // Texture coordinates and tangents go with their vertices too: a shared mesh's textures
            // (an emitting one's emission texture, flattened per node) read them.
            if (!mesh.uvs.empty()) out.uvs.push_back(mesh.uvs[v]);
            if (!mesh.second_uvs.empty()) out.second_uvs.push_back(mesh.second_uvs[v]);
            if (!mesh.tangents.empty()) out.tangents.push_back(mesh.tangents[v]);
        }
    }
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        const auto& tri = mesh.triangles[t];
        ImportedMesh& out = *target[owner[tri[0]]];
        out.triangles.push_back({new_index[tri[0]], new_index[tri[1]], new_index[tri[2]]});
        if (!mesh.triangle_materials.empty()) out.triangle_materials.push_back(mesh.triangle_materials[t]);
    }
    for (ImportedMesh* out : target) out->materials = mesh.materials;
    stays.notes = std::move(mesh.notes);
    stays.placements = std::move(mesh.placements);
    mesh = std::move(stays);
    return shared;
}

}  // namespace wt
