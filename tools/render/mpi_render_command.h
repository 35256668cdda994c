#pragma once
// `wavetrace render` under mpirun: the command's side of mpi_render.h (which options
// apply, what rank 0 writes and prints). Built only with -DWAVETRACE_MPI=ON.

#include "core/checkpoint/checkpoint.h"
#include "kernels/renderer.h"
#include "tools/render/render_command_options.h"

namespace wt {

// Throws std::runtime_error naming the first option a distributed render does not support.
void check_mpi_render_options(const RenderCommandOptions& options);

// Renders samples [0, spp) over the ranks; rank 0 writes the outputs (`header`: the scene's,
// its range filled in here) and the summary. Returns the exit code.
int run_render_on_mpi_ranks(const RenderCommandOptions& options, RenderSession& session, const Scene& scene,
                            CheckpointHeader header);

}  // namespace wt
