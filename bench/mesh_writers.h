#pragma once
// A TriangleMesh written out in the three formats the scene loader's mesh_file shape reads, so
// the importers can be timed and checked on the benchmark meshes. Written by hand: each format
// is a few lines of header and flat arrays, and the benchmarks must not need a writer library.
//
// Every writer writes through write_file_atomically (atomic_file.h): the file appears whole or
// not at all. Failures throw std::runtime_error naming the file. Vertex normals are written when the mesh
// has them (one per vertex).

#include <string>

#include "core/description/scene_description.h"

namespace wt::bench {

// PLY, binary_little_endian 1.0: vertex x y z [nx ny nz] as float, face vertex_indices as a
// list uchar uint. `comment` becomes a header comment line.
void write_ply(const std::string& path, const TriangleMesh& mesh, const std::string& comment);

// Wavefront OBJ: v (and vn) lines with the shortest decimal that reads back as the same float,
// then f lines (a//a b//b c//c when there are normals), 1-based. `comment` becomes a # line.
void write_obj(const std::string& path, const TriangleMesh& mesh, const std::string& comment);

// glTF 2.0 binary (.glb): one buffer, one mesh with one TRIANGLES primitive (POSITION with its
// min/max, NORMAL, uint32 indices), one node, one scene. `generator` goes to asset.generator.
void write_glb(const std::string& path, const TriangleMesh& mesh, const std::string& generator);

}  // namespace wt::bench
