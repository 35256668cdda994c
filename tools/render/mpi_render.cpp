#include "tools/render/mpi_render.h"

#include <mpi.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <thread>
#include <vector>

#include "tools/render/chunk_dispatch.h"

namespace wt {

namespace {

bool initialised = false;
int world_rank = 0, world_size = 1;

enum Tag : int { tag_identity = 1, tag_request, tag_assign, tag_ranges, tag_counts, tag_sums, tag_rays };

void check(int rc, const char* what) {
    if (rc == MPI_SUCCESS) return;
    char text[MPI_MAX_ERROR_STRING];
    int length = 0;
    MPI_Error_string(rc, text, &length);
    throw std::runtime_error(std::string("MPI: ") + what + " failed: " + std::string(text, std::size_t(length)));
}

// mpirun (OpenMPI) and PMI launchers (MPICH, Slurm's srun) say how many ranks there are.
int launcher_world_size() {
    for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"})
        if (const char* v = std::getenv(name)) return std::atoi(v);
    return 1;
}

// Pieces under MPI's int count limit.
constexpr std::size_t piece_bytes = std::size_t(1) << 30;

void send_bytes(const void* data, std::size_t bytes, int tag) {
    const char* p = static_cast<const char*>(data);
    for (std::size_t done = 0; done < bytes || done == 0; done += piece_bytes) {
        const int n = int(std::min(piece_bytes, bytes - done));
        check(MPI_Send(p + done, n, MPI_BYTE, 0, tag, MPI_COMM_WORLD), "sending the film");
        if (bytes == 0) break;
    }
}

void receive_bytes(void* data, std::size_t bytes, int source, int tag) {
    char* p = static_cast<char*>(data);
    for (std::size_t done = 0; done < bytes || done == 0; done += piece_bytes) {
        const int n = int(std::min(piece_bytes, bytes - done));
        MPI_Status status;
        check(MPI_Recv(p + done, n, MPI_BYTE, source, tag, MPI_COMM_WORLD, &status), "receiving a film");
        int got = 0;
        MPI_Get_count(&status, MPI_BYTE, &got);
        if (got != n)
            throw std::runtime_error("MPI: rank " + std::to_string(source) + " sent " + std::to_string(got) +
                                     " bytes of film where " + std::to_string(n) + " were expected");
        if (bytes == 0) break;
    }
}

// Every rank must render the same image: rank 0's scene hash, settings and size are the reference.
void check_identity(const std::string& identity) {
    unsigned long long length = identity.size();
    check(MPI_Bcast(&length, 1, MPI_UNSIGNED_LONG_LONG, 0, MPI_COMM_WORLD), "comparing the ranks' scenes");
    std::string reference(std::size_t(length), '\0');
    if (world_rank == 0) reference = identity;
    check(MPI_Bcast(reference.data(), int(length), MPI_CHAR, 0, MPI_COMM_WORLD), "comparing the ranks' scenes");
    if (reference != identity)
        throw std::runtime_error("MPI rank " + std::to_string(world_rank) + " would render another image than rank 0 (" +
                                 identity + " here, " + reference + " on rank 0): the scene file or options differ");
}

// A blocking receive that does not spin a core while rank 0's own chunks render beside it.
void receive_polling(void* data, int count, MPI_Datatype type, int tag, MPI_Status& status) {
    MPI_Request request;
    check(MPI_Irecv(data, count, type, MPI_ANY_SOURCE, tag, MPI_COMM_WORLD, &request), "waiting for a rank");
    for (int done = 0;;) {
        check(MPI_Test(&request, &done, &status), "waiting for a rank");
        if (done) return;
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
}

DistributedRenderResult dispatch_and_reduce(RenderSession& session, Film& film, SampleRange samples, bool quiet) {
    DistributedRenderResult result;
    std::vector<RankRanges> ranges{{0, {}}};
    {
        // On a failure here, leaving this block stops rank 0's own renderer after its chunk.
        ChunkDispatch dispatch(samples, world_size, quiet, [&](SampleRange r) { session.render_samples(film, r); });
        while (dispatch.remote_ranks_working()) {
            uint32_t done[2];
            MPI_Status status;
            receive_polling(done, 2, MPI_UINT32_T, tag_request, status);
            const SampleRange next = dispatch.answer(status.MPI_SOURCE, {done[0], done[1]});
            const uint32_t assign[2] = {next.begin, next.end};
            check(MPI_Send(assign, 2, MPI_UINT32_T, status.MPI_SOURCE, tag_assign, MPI_COMM_WORLD), "handing out samples");
        }
        ranges[0].ranges = dispatch.finish_local();
    }
    result.counts = session.result().counts;

    // In rank order, so the reduction is one fixed sequence (the sums are exact in any order).
    for (int rank = 1; rank < world_size; ++rank) {
        MPI_Status status;
        check(MPI_Probe(rank, tag_ranges, MPI_COMM_WORLD, &status), "receiving a film");
        int n = 0;
        MPI_Get_count(&status, MPI_UINT32_T, &n);
        std::vector<uint32_t> flat(std::size_t(std::max(n, 0)));
        check(MPI_Recv(flat.data(), n, MPI_UINT32_T, rank, tag_ranges, MPI_COMM_WORLD, MPI_STATUS_IGNORE), "receiving a film");
        RankRanges r{rank, {}};
        for (std::size_t i = 0; i + 1 < flat.size(); i += 2) r.ranges.push_back({flat[i], flat[i + 1]});
        // The rank traced the light paths of every sample it rendered: what its splats are over.
        uint64_t rank_samples = 0;
        for (const SampleRange& range : r.ranges) rank_samples += range.size();
        ranges.push_back(std::move(r));
        Film part(film.width(), film.height(), film.extra_channels());
        receive_bytes(part.raw_counts().data(), part.raw_counts().size() * sizeof(uint32_t), rank, tag_counts);
        receive_bytes(part.raw_sums().data(), part.raw_sums().size() * sizeof(FixedPoint), rank, tag_sums);
        if (part.has_splats()) part.set_splat_samples(rank_samples);
        RayCounts counts;
        receive_bytes(&counts, sizeof counts, rank, tag_rays);
        film.add_film(part);
        result.counts += counts;
    }
    check_coverage(ranges, samples);
    for (const RankRanges& r : ranges) result.chunks += uint32_t(r.ranges.size());
    return result;
}

DistributedRenderResult render_and_send(RenderSession& session, Film& film) {
    std::vector<uint32_t> flat;
    uint32_t done[2] = {0, 0};
    for (;;) {
        check(MPI_Send(done, 2, MPI_UINT32_T, 0, tag_request, MPI_COMM_WORLD), "asking rank 0 for samples");
        uint32_t assign[2];
        check(MPI_Recv(assign, 2, MPI_UINT32_T, 0, tag_assign, MPI_COMM_WORLD, MPI_STATUS_IGNORE), "asking rank 0 for samples");
        if (assign[0] == assign[1]) break;
        session.render_samples(film, {assign[0], assign[1]});
        flat.push_back(assign[0]), flat.push_back(assign[1]);
        done[0] = assign[0], done[1] = assign[1];
    }
    DistributedRenderResult result;
    result.counts = session.result().counts;
    result.chunks = uint32_t(flat.size() / 2);
    check(MPI_Send(flat.data(), int(flat.size()), MPI_UINT32_T, 0, tag_ranges, MPI_COMM_WORLD), "sending the film");
    send_bytes(film.raw_counts().data(), film.raw_counts().size() * sizeof(uint32_t), tag_counts);
    send_bytes(film.raw_sums().data(), film.raw_sums().size() * sizeof(FixedPoint), tag_sums);
    send_bytes(&result.counts, sizeof result.counts, tag_rays);
    return result;
}

}  // namespace

MpiJob::MpiJob(int& argc, char**& argv) {
    if (launcher_world_size() < 2) return;
    int provided = 0;
    // Only the main thread calls MPI; rank 0 renders on another.
    if (MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided) != MPI_SUCCESS) {
        std::fprintf(stderr, "wavetrace: error: MPI: initialisation failed\n");
        std::exit(1);
    }
    initialised = true;
    MPI_Comm_set_errhandler(MPI_COMM_WORLD, MPI_ERRORS_RETURN);  // errors become messages, not silent aborts
    MPI_Comm_rank(MPI_COMM_WORLD, &world_rank);
    MPI_Comm_size(MPI_COMM_WORLD, &world_size);
}

MpiJob::~MpiJob() {
    if (initialised) MPI_Finalize();
}

bool MpiJob::active() { return initialised && world_size > 1; }
int MpiJob::rank() { return world_rank; }
int MpiJob::size() { return world_size; }

void MpiJob::abort(int status) {
    std::fflush(stderr);
    MPI_Abort(MPI_COMM_WORLD, status);
    std::exit(status);
}

DistributedRenderResult render_distributed(RenderSession& session, Film& film, SampleRange samples,
                                           const std::string& identity, bool quiet) {
    const auto start = std::chrono::steady_clock::now();
    if (!quiet) {
        char host[256] = "?";
        gethostname(host, sizeof host - 1);
        std::fprintf(stderr, "wavetrace: MPI rank %d of %d on %s, pid %ld, %d thread%s\n", world_rank, world_size, host,
                     long(getpid()), session.result().threads, session.result().threads > 1 ? "s" : "");
    }
    check_identity(identity);
    DistributedRenderResult result =
        world_rank == 0 ? dispatch_and_reduce(session, film, samples, quiet) : render_and_send(session, film);
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
}

}  // namespace wt
