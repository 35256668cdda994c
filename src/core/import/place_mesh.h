#pragma once
// What every format's mesh goes through on its way into the scene: its pieces placed by their
// transforms, zero-area triangles dropped, and the shading normals chosen.

#include <cstddef>

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

#include "core/import/imported_mesh.h"

namespace wt {

enum class NormalsMode {
    file,    // the file's vertex normals if it has them, else none (flat)
    smooth,  // angle-weighted vertex normals (vertex_normals.h), whatever the file has
    flat,    // none: shade with the geometric normal
};

// In place. Positions go through scene_transform * piece.transform (in double, rounded to float
// once; not at all when that product is exactly the identity, so the file's floats stay bit for
// bit), normals through its inverse transpose and are renormalised. A piece whose transform
// mirrors (negative determinant) has its triangles' winding reversed, so the front face stays
// the side its normals point to. Returns how many zero-area triangles were dropped (judged after
// the transform, as triangle_size.h does for the scene's own triangles). Tangents
// (TriangleMesh::tangents) go through placed_tangent().
std::size_t place_mesh(ImportedMesh& mesh, const glm::dmat4& scene_transform, NormalsMode normals);

// A tangent through a linear map: its direction renormalised, w's sign flipped where the map
// mirrors; one that comes out without a direction is none (w = 0, the triangle's own frame).
glm::vec4 placed_tangent(const glm::vec4& t, const glm::dmat3& linear);

}  // namespace wt
