#include "core/geometry/mikktspace_tangents.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstring>
#include <unordered_map>

#include <glm/geometric.hpp>

namespace wt {
namespace {

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// v / |v|, or zero where v has no direction. Divided rather than multiplied by an inverse
// square root, so that an axis comes out exactly an axis.
glm::vec3 unit_or_zero(const glm::vec3& v) {
    const float length = glm::length(v);
    return length > FLT_MIN && std::isfinite(length) ? v / length : glm::vec3(0.0f);
}

// Some unit vector orthogonal to n: the cross product with the axis n is least along.
glm::vec3 any_orthogonal(const glm::vec3& n) {
    const glm::vec3 a = std::fabs(n.x) <= std::fabs(n.y) && std::fabs(n.x) <= std::fabs(n.z) ? glm::vec3(1, 0, 0)
                        : std::fabs(n.y) <= std::fabs(n.z)                                   ? glm::vec3(0, 1, 0)
                                                                                             : glm::vec3(0, 0, 1);
    const glm::vec3 t = unit_or_zero(glm::cross(a, n));
    return t == glm::vec3(0.0f) ? glm::vec3(1, 0, 0) : t;
}

// What welds two corners: MikkTSpace treats corners with the same position, normal and
// coordinates as one vertex, whatever their indices (files often split vertices for other
// attributes).
struct CornerKey {
    float values[8];
    bool operator==(const CornerKey& o) const { return std::memcmp(values, o.values, sizeof values) == 0; }
};
struct CornerKeyHash {
    std::size_t operator()(const CornerKey& k) const {
        uint64_t h = 1469598103934665603ull;
        for (float f : k.values) {
            uint32_t bits;
            std::memcpy(&bits, &f, 4);
            h = (h ^ bits) * 1099511628211ull;
        }
        return std::size_t(h);
    }
};

struct Face {
    glm::vec3 tangent{0.0f};  // unit dP/du, or zero for a degenerate mapping
    bool positive = true;     // the sign of the (u, -v) area: whether the mapping keeps the winding
};

}  // namespace

std::vector<glm::vec4> mikktspace_tangents(const std::vector<glm::vec3>& positions, const std::vector<glm::vec3>& normals,
                                           const std::vector<glm::vec2>& uvs,
                                           const std::vector<std::array<uint32_t, 3>>& triangles) {
    const std::size_t corners = 3 * triangles.size();
    // Each face's tangent from its texture-space derivatives (Mikkelsen 2008, sec. 3): with
    // (s, t) = (u, -v), dP/ds solved from the edges; only its direction and the sign of the
    // texture-space area are kept here (glTF stores no bitangent magnitude).
    std::vector<Face> faces(triangles.size());
    std::vector<glm::vec3> corner_normals(corners);
    for (std::size_t f = 0; f < triangles.size(); ++f) {
        const auto& tri = triangles[f];
        const glm::vec3 d1 = positions[tri[1]] - positions[tri[0]], d2 = positions[tri[2]] - positions[tri[0]];
        const glm::vec3 face_normal = unit_or_zero(glm::cross(d1, d2));
        for (int c = 0; c < 3; ++c) {
            const glm::vec3 n = normals.empty() ? glm::vec3(0.0f) : unit_or_zero(normals[tri[c]]);
            corner_normals[3 * f + c] = n == glm::vec3(0.0f) ? (face_normal == glm::vec3(0.0f) ? glm::vec3(0, 0, 1) : face_normal) : n;
        }
        const glm::vec2 st0(uvs[tri[0]].x, -uvs[tri[0]].y), st1(uvs[tri[1]].x, -uvs[tri[1]].y), st2(uvs[tri[2]].x, -uvs[tri[2]].y);
        const glm::vec2 t21 = st1 - st0, t31 = st2 - st0;
        const float area = t21.x * t31.y - t21.y * t31.x;
        faces[f].positive = area > 0.0f;
        if (!(std::fabs(area) > FLT_MIN)) continue;  // degenerate: takes its neighbours' (below)
        const glm::vec3 os = t31.y * d1 - t21.y * d2;  // dP/ds times the area
        const glm::vec3 tangent = unit_or_zero(area > 0.0f ? os : -os);
        if (finite(tangent)) faces[f].tangent = tangent;
    }

    // Corners welded into vertices, and each vertex split by the faces' handedness: a mirrored
    // UV island meets its original along a seam whose two sides need opposite bitangents. (The
    // reference further splits a vertex's faces of one handedness into fans joined by shared
    // edges; here they are one group, which differs only where such fans touch at a point.)
    std::unordered_map<CornerKey, uint32_t, CornerKeyHash> welded;
    std::vector<uint32_t> vertex_of(corners);
    for (std::size_t f = 0; f < triangles.size(); ++f)
        for (int c = 0; c < 3; ++c) {
            const uint32_t v = triangles[f][c];
            const glm::vec3& p = positions[v];
            const glm::vec3& n = corner_normals[3 * f + c];
            const CornerKey key{{p.x, p.y, p.z, n.x, n.y, n.z, uvs[v].x, uvs[v].y}};
            vertex_of[3 * f + c] = welded.emplace(key, uint32_t(welded.size())).first->second;
        }
    // Accumulated per (vertex, handedness): each face's tangent projected into the plane of
    // the vertex normal, weighted by the face's angle at the corner in that plane.
    std::vector<glm::vec3> sums(2 * welded.size(), glm::vec3(0.0f));
    std::vector<bool> used(2 * welded.size(), false);
    for (std::size_t f = 0; f < triangles.size(); ++f) {
        if (faces[f].tangent == glm::vec3(0.0f)) continue;
        for (int c = 0; c < 3; ++c) {
            const glm::vec3& n = corner_normals[3 * f + c];
            const glm::vec3 p = positions[triangles[f][c]];
            const glm::vec3 a = positions[triangles[f][(c + 1) % 3]] - p, b = positions[triangles[f][(c + 2) % 3]] - p;
            const glm::vec3 ea = unit_or_zero(a - glm::dot(a, n) * n), eb = unit_or_zero(b - glm::dot(b, n) * n);
            const float angle = std::acos(std::clamp(glm::dot(ea, eb), -1.0f, 1.0f));
            const glm::vec3 t = unit_or_zero(faces[f].tangent - glm::dot(faces[f].tangent, n) * n);
            const std::size_t group = 2 * vertex_of[3 * f + c] + (faces[f].positive ? 0 : 1);
            sums[group] += angle * t;
            used[group] = true;
        }
    }

    std::vector<glm::vec4> out(corners);
    for (std::size_t f = 0; f < triangles.size(); ++f)
        for (int c = 0; c < 3; ++c) {
            const std::size_t corner = 3 * f + c, vertex = vertex_of[corner];
            const glm::vec3& n = corner_normals[corner];
            // A degenerate face has no handedness of its own: it takes what the good faces at
            // its vertices made (MikkTSpace's degenerate epilogue), the positive side first.
            bool positive = faces[f].positive;
            if (faces[f].tangent == glm::vec3(0.0f)) positive = used[2 * vertex] || !used[2 * vertex + 1];
            const glm::vec3 sum = sums[2 * vertex + (positive ? 0 : 1)];
            glm::vec3 t = unit_or_zero(sum - glm::dot(sum, n) * n);
            if (t == glm::vec3(0.0f)) t = any_orthogonal(n);
            out[corner] = glm::vec4(t, positive ? 1.0f : -1.0f);
        }
    return out;
}

}  // namespace wt
