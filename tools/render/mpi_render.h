#pragma once
// A render spread over the ranks of an MPI job: `mpirun -np N wavetrace render SCENE ...`.
// Built only with -DWAVETRACE_MPI=ON (OpenMPI); the default build has none of this.
//
// Rank 0 hands out chunks of whole sample ranges ([b, e) of every pixel) as ranks ask for
// them, so a faster machine takes more; it renders chunks itself on a thread beside the one
// that answers. Each rank renders into a film of its own, with its own threads. At the end rank
// 0 receives the films in rank order, checks that the chunks they hold cover the render's
// samples exactly once, adds them (exact sums: the bits of a one-process render) and alone
// writes the outputs. A rank that dies ends the job (mpirun kills the others and says which
// rank died); no image is written, since rank 0 never has all the samples.

#include <string>

#include "core/film/film.h"
#include "kernels/work/render_stats.h"
#include "kernels/renderer.h"

namespace wt {

// MPI for the life of the process, when it is one of several ranks started by mpirun (its
// environment says so; a plain run never initialises MPI, which costs start-up time).
class MpiJob {
public:
    MpiJob(int& argc, char**& argv);
    ~MpiJob();
    MpiJob(const MpiJob&) = delete;
    MpiJob& operator=(const MpiJob&) = delete;

    static bool active();  // running as one of two or more ranks
    static int rank();
    static int size();
    // Ends every rank of the job with `status` (after an error on one rank, so the others do
    // not wait for it forever).
    [[noreturn]] static void abort(int status);
};

struct DistributedRenderResult {
    RayCounts counts;  // of every rank (rank 0's return value; the others' own)
    double seconds = 0.0;
    uint32_t chunks = 0;
};

// Called by every rank with the same scene and settings; `identity` (scene hash, settings,
// size) is compared with rank 0's first, and a rank whose scene or options differ stops the
// job with a message. On return on rank 0, `film` holds every sample of `samples`. Throws
// std::runtime_error on an MPI failure or when the ranks' chunks do not add up.
DistributedRenderResult render_distributed(RenderSession& session, Film& film, SampleRange samples,
                                           const std::string& identity, bool quiet);

}  // namespace wt
