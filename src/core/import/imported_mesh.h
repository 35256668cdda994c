#pragma once
// What a mesh file holds, as its format reader found it: plain data, in the file's own
// coordinates, before the scene's transform, degenerate triangles or normals are dealt with
// (place_mesh.h does that, the same way for every format).

#include <array>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "core/description/scene_description.h"

namespace wt {

// A format reader's complaint, "FILE:LINE: problem" or "FILE: byte N: problem" or "FILE:
// accessor 3: problem": whatever the format lets it name. The scene loader prefixes the scene
// file and the JSON path of the shape.
struct MeshFileError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// A range of vertices that the file places with one matrix (glTF: a node's world transform;
// OBJ and PLY: one piece, the identity).
struct MeshPiece {
    std::size_t first_vertex = 0;
    std::size_t vertex_count = 0;
    glm::dmat4 transform{1.0};
    // A piece of a mesh the file places more than once (glTF: a mesh several nodes use): the
    // index of that shared mesh, its vertices stored once in its own space (transform the
    // identity) and placed by ImportedMesh::placements. kNotShared for every other piece.
    uint32_t shared = kNotShared;
    static constexpr uint32_t kNotShared = UINT32_MAX;
};

// One placement of a shared mesh: the node's world transform.
struct SharedMeshPlacement {
    uint32_t shared = 0;
    glm::dmat4 transform{1.0};
};

// A material as the file describes it, already mapped to ours; `name` is the file's own.
struct ImportedMaterial {
    Material material;
    std::vector<std::string> unmapped;  // what the file said that we cannot render (textures...)
};

struct ImportedMesh {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;  // the file's vertex normals: empty, or one per position
    // Texture coordinates (v = 0 the image's top row): empty, or one per position.
    std::vector<glm::vec2> uvs;
    // TEXCOORD_1 (TriangleMesh::second_uvs): empty, or one per position.
    std::vector<glm::vec2> second_uvs;
    // Normal-map tangents (TriangleMesh::tangents): empty, or one per position.
    std::vector<glm::vec4> tangents;
    std::vector<std::array<uint32_t, 3>> triangles;
    // Per triangle, an index into `materials`, or kNoMaterial; empty when the file has none.
    std::vector<uint32_t> triangle_materials;
    std::vector<ImportedMaterial> materials;
    std::vector<TextureImage> textures;  // what the materials' color_texture and the like index
    std::vector<MeshPiece> pieces;   // cover `positions` in order
    std::vector<SharedMeshPlacement> placements;  // empty unless some piece is shared
    uint32_t shared_count = 0;
    std::vector<std::string> notes;  // what was skipped, for the user (one line each)
    // Lights the file places (glTF's KHR_lights_punctual), in its coordinates with the pieces'
    // transforms applied, as the scene's "lights" list holds them.
    std::vector<LightDescription> lights;

    static constexpr uint32_t kNoMaterial = UINT32_MAX;
};

}  // namespace wt
