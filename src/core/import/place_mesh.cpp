#include "core/import/place_mesh.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "core/import/vertex_normals.h"
#include "core/geometry/triangle_size.h"

namespace wt {
namespace {

void transform_positions(ImportedMesh& mesh, const MeshPiece& piece, const glm::dmat4& m) {
    const std::size_t end = piece.first_vertex + piece.vertex_count;
    for (std::size_t v = piece.first_vertex; v < end; ++v)
        mesh.positions[v] = glm::vec3(m * glm::dvec4(glm::dvec3(mesh.positions[v]), 1.0));
}

// Renormalises even under the identity: files do not promise unit normals. Returns false where
// a normal came out zero or not finite (a zero normal in the file, or a singular transform).
bool transform_normals(ImportedMesh& mesh, const MeshPiece& piece, const glm::dmat4& m) {
    const glm::dmat3 normal_matrix = glm::transpose(glm::inverse(glm::dmat3(m)));
    bool all_valid = true;
    const std::size_t end = piece.first_vertex + piece.vertex_count;
    for (std::size_t v = piece.first_vertex; v < end; ++v) {
        const glm::dvec3 n = normal_matrix * glm::dvec3(mesh.normals[v]);
        const double length = glm::length(n);
        const bool valid = length > 0.0 && std::isfinite(length);
        all_valid &= valid;
        mesh.normals[v] = valid ? glm::vec3(n / length) : glm::vec3(NAN);
    }
    return all_valid;
}

void transform_tangents(ImportedMesh& mesh, const MeshPiece& piece, const glm::dmat4& m) {
    const std::size_t end = piece.first_vertex + piece.vertex_count;
    for (std::size_t v = piece.first_vertex; v < end; ++v) mesh.tangents[v] = placed_tangent(mesh.tangents[v], glm::dmat3(m));
}

}  // namespace

// The bitangent cross(n, t) w has its side flipped by a mirroring map (normals going through the
// inverse transpose): w changes sign with the determinant.
glm::vec4 placed_tangent(const glm::vec4& t, const glm::dmat3& linear) {
    if (t.w == 0.0f) return t;
    const glm::dvec3 d = linear * glm::dvec3(t.x, t.y, t.z);
    const double length = glm::length(d);
    if (!(length > 0.0) || !std::isfinite(length)) return glm::vec4(0.0f);
    return glm::vec4(glm::vec3(d / length), glm::determinant(linear) < 0.0 ? -t.w : t.w);
}

std::size_t place_mesh(ImportedMesh& mesh, const glm::dmat4& scene_transform, NormalsMode normals) {
    if (normals != NormalsMode::file) mesh.normals.clear();
    bool normals_valid = true;
    std::vector<bool> mirrored(mesh.pieces.size(), false);
    bool any_mirrored = false;
    for (std::size_t p = 0; p < mesh.pieces.size(); ++p) {
        const MeshPiece& piece = mesh.pieces[p];
        const glm::dmat4 m = scene_transform * piece.transform;
        if (m != glm::dmat4(1.0)) transform_positions(mesh, piece, m);
        if (!mesh.normals.empty()) normals_valid &= transform_normals(mesh, piece, m);
        if (!mesh.tangents.empty() && m != glm::dmat4(1.0)) transform_tangents(mesh, piece, m);
        mirrored[p] = glm::determinant(glm::dmat3(m)) < 0.0;
        any_mirrored |= mirrored[p];
    }
    if (any_mirrored) {
        // A triangle belongs to the piece holding its first vertex; pieces are in vertex order.
        const auto piece_of = [&](uint32_t v) {
            const auto after = std::upper_bound(mesh.pieces.begin(), mesh.pieces.end(), std::size_t(v),
                                                [](std::size_t x, const MeshPiece& q) { return x < q.first_vertex; });
            return std::size_t(after - mesh.pieces.begin()) - 1;
        };
        for (auto& tri : mesh.triangles)
            if (mirrored[piece_of(tri[0])]) std::swap(tri[1], tri[2]);
    }

    std::size_t kept = 0;
    const bool per_triangle_materials = !mesh.triangle_materials.empty();
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        const auto& tri = mesh.triangles[t];
        if (triangle_size(mesh.positions[tri[0]], mesh.positions[tri[1]], mesh.positions[tri[2]]).degenerate()) continue;
        mesh.triangles[kept] = tri;
        if (per_triangle_materials) mesh.triangle_materials[kept] = mesh.triangle_materials[t];
        ++kept;
    }
    const std::size_t dropped = mesh.triangles.size() - kept;
    mesh.triangles.resize(kept);
    if (per_triangle_materials) mesh.triangle_materials.resize(kept);

    if (normals == NormalsMode::smooth) {
        mesh.normals = angle_weighted_normals(mesh.positions, mesh.triangles);
    } else if (!normals_valid) {
        // The file's normal is unusable at some vertex: the smooth normal is the nearest thing
        // to what the file meant there; elsewhere the file's stay.
        const std::vector<glm::vec3> smooth = angle_weighted_normals(mesh.positions, mesh.triangles);
        for (std::size_t v = 0; v < mesh.normals.size(); ++v) {
            const glm::vec3& n = mesh.normals[v];
            if (!(std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z))) mesh.normals[v] = smooth[v];
        }
    }
    return dropped;
}

}  // namespace wt
