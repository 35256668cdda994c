#pragma once
// The scenes the benchmarks measure: the reference hexroom (scenes/hexroom.json), so the
// numbers speak about the geometry the renderer is built for, and the hexroom with one big mesh
// in its air, for the BVH: a displaced sphere of about 10k, 100k or 1M triangles
// (displaced_sphere.h) or a real model from Debian's assimp-testmodels package.
//
//   hexroom                   the reference scene alone: 7 parallelograms, 12 triangles, 4 spheres
//   hexroom_mesh10k           + the displaced sphere 100 x 50 segments (9,800 triangles)
//   hexroom_mesh100k          + 316 x 158 (99,224 triangles)
//   hexroom_mesh1m            + 1000 x 499 (996,000 triangles)
//   hexroom_2cylinderengine   + assimp-testmodels' glTF2/2CylinderEngine.glb (29 meshes of
//                             75,730 triangles, some instanced by several of its 82 nodes:
//                             110,336 triangles in the scene), its bounding box fitted into the
//                             sphere's ball

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/description/scene_description.h"
#include "displaced_sphere.h"
#include "workloads.h"

namespace wt::bench {

// The hexroom as its file describes it, at the resolution and sample count a benchmark needs.
SceneDescription hexroom_description(int width, int height, int spp);

// The grey Lambertian (albedo 0.8) a mesh added to the hexroom is made of, named `name`.
Material added_mesh_material(const std::string& name);

// The hexroom with benchmark mesh `mesh` in it, as make_displaced_sphere wrote it into
// `data_directory` (bench_data.h): load_scene_file of bench_scene_file(data_directory, mesh),
// which holds the mesh as a mesh_file shape (its last mesh, material added_mesh_material).
// Throws SceneUnavailable if the file is missing (the bench_data target writes it) or does not
// load.
SceneDescription hexroom_with_sphere_description(const std::string& data_directory, const BenchmarkMesh& mesh, int width,
                                                 int height, int spp);

// Scales (uniformly) and moves `meshes` so their common bounding box is centred on the ball
// and its corners lie on it. Normals need no change under a uniform scale and a translation.
void fit_into_ball(std::vector<TriangleMesh>& meshes, const Ball& ball);

// A scene bench_intersect measures.
struct BenchScene {
    std::string name;
    SceneDescription description;
    std::optional<Ball> solid;  // the added mesh's bounding ball (incoherent ray origins avoid it)
};

// Why a scene cannot be built on this machine (a missing bench-only package, a file format the
// scene loader does not read yet); what() says what is missing and how to get it.
struct SceneUnavailable : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Every scene above, in the order listed.
std::vector<std::string> bench_scene_names();

// The scene `name`, one sample per pixel at width x height; the sphere scenes from
// build/bench-data (WT_BENCH_DATA_DIR). Throws SceneUnavailable, or std::invalid_argument for a
// name not in bench_scene_names().
BenchScene bench_scene(const std::string& name, int width, int height);

}  // namespace wt::bench
