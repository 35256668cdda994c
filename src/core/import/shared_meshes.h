#pragma once
// Splitting a file's shared meshes (MeshPiece::shared) out of what it places once, so the scene
// can store each once and place it by instances.

#include <vector>

#include "core/import/imported_mesh.h"

namespace wt {

// Moves every shared piece out of `mesh` into the ImportedMesh of its shared index (in that
// mesh's own space, with all of the file's materials, in the file's vertex order); what stays in
// `mesh` is what the file places once. mesh.placements is left as it was.
std::vector<ImportedMesh> take_shared_meshes(ImportedMesh& mesh);

}  // namespace wt
