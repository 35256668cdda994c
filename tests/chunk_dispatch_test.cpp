// Rank 0's hand-out of sample chunks in an MPI render (tools/render/chunk_dispatch.h), run with
// its real threads: the local renderer on its own thread, and this thread playing the loop of
// mpi_render.cpp that answers the other ranks, with the ranks simulated. Under ThreadSanitizer
// (`make test-tsan`) this is the MPI render's rank 0 without mpirun.

#include <gtest/gtest.h>

#include <future>
#include <stdexcept>
#include <string>
#include <vector>

#include "tools/render/chunk_dispatch.h"

namespace wt {
namespace {

// A rank other than 0 as rank 0 sees it: it asks with the chunk it last rendered.
struct RemoteRank {
    int rank;
    SampleRange held{0, 0};
    bool stopped = false;
    std::vector<SampleRange> rendered;
};

// mpi_render.cpp's loop, with the ranks' requests arriving in turn (a rank told to stop asks no
// more, as a real one leaves the loop). Returns the remote ranks, every one of them stopped.
std::vector<RemoteRank> serve_remote_ranks(ChunkDispatch& dispatch, int ranks) {
    std::vector<RemoteRank> remote;
    for (int r = 1; r < ranks; ++r) remote.push_back(RemoteRank{r, {0, 0}, false, {}});
    for (std::size_t turn = 0; dispatch.remote_ranks_working(); ++turn) {
        RemoteRank& asking = remote[turn % remote.size()];
        if (asking.stopped) continue;
        const SampleRange next = dispatch.answer(asking.rank, asking.held);
        asking.held = next;
        if (next.size() == 0) asking.stopped = true;
        else asking.rendered.push_back(next);
    }
    return remote;
}

std::vector<RankRanges> all_ranges(const std::vector<SampleRange>& local, const std::vector<RemoteRank>& remote) {
    std::vector<RankRanges> all{{0, local}};
    for (const RemoteRank& r : remote) all.push_back({r.rank, r.rendered});
    return all;
}

std::size_t chunk_count(const std::vector<RankRanges>& all) {
    std::size_t n = 0;
    for (const RankRanges& r : all) n += r.ranges.size();
    return n;
}

TEST(ChunkDispatch, EveryChunkHandedOutOnceWhileTheLocalThreadRenders) {
    for (const int ranks : {2, 3, 5})
        for (const SampleRange samples : {SampleRange{0, 1}, SampleRange{0, 7}, SampleRange{5, 69}, SampleRange{0, 1000}}) {
            SCOPED_TRACE(std::to_string(ranks) + " ranks, samples " + std::to_string(samples.begin) + ":" +
                         std::to_string(samples.end));
            std::vector<SampleRange> seen_by_render;  // the local thread's alone until finish_local
            ChunkDispatch dispatch(samples, ranks, true, [&](SampleRange r) { seen_by_render.push_back(r); });
            const std::vector<RemoteRank> remote = serve_remote_ranks(dispatch, ranks);
            const std::vector<SampleRange> local = dispatch.finish_local();

            for (const RemoteRank& r : remote) EXPECT_TRUE(r.stopped) << "rank " << r.rank;
            EXPECT_EQ(local.size(), seen_by_render.size());
            const std::vector<RankRanges> all = all_ranges(local, remote);
            EXPECT_NO_THROW(check_coverage(all, samples));
            const uint32_t chunk = chunk_size(samples, ranks);
            EXPECT_EQ(chunk_count(all), (samples.size() + chunk - 1) / chunk);
            EXPECT_EQ(dispatch.samples_done(), samples.size());
        }
}

TEST(ChunkDispatch, RanksAskingAfterTheLocalThreadTookEverythingAreToldToStop) {
    const SampleRange samples{0, 40};
    ChunkDispatch dispatch(samples, 3, true, [](SampleRange) {});
    const std::vector<SampleRange> local = dispatch.finish_local();
    EXPECT_NO_THROW(check_coverage({{0, local}}, samples));
    EXPECT_EQ(dispatch.answer(1, {0, 0}).size(), 0u);
    EXPECT_TRUE(dispatch.remote_ranks_working());
    EXPECT_EQ(dispatch.answer(2, {0, 0}).size(), 0u);
    EXPECT_FALSE(dispatch.remote_ranks_working());
    EXPECT_EQ(dispatch.samples_done(), samples.size());
}

TEST(ChunkDispatch, RemoteRanksRenderTheRestWhenTheLocalThreadFails) {
    const SampleRange samples{0, 64};
    std::promise<SampleRange> failing;
    ChunkDispatch dispatch(samples, 3, true, [&](SampleRange r) {
        failing.set_value(r);
        throw std::runtime_error("out of memory in the film");
    });
    // The remote ranks ask once the local thread holds its chunk, so that it holds one.
    const SampleRange failed = failing.get_future().get();
    const std::vector<RemoteRank> remote = serve_remote_ranks(dispatch, 3);
    try {
        dispatch.finish_local();
        FAIL() << "the local thread's failure was not rethrown";
    } catch (const std::runtime_error& e) {
        EXPECT_STREQ(e.what(), "out of memory in the film");
    }
    // The failed chunk was not rendered, and every other chunk went to a remote rank.
    std::vector<RankRanges> all = all_ranges({}, remote);
    EXPECT_THROW(check_coverage(all, samples), std::runtime_error);
    all.push_back({0, {failed}});
    EXPECT_NO_THROW(check_coverage(all, samples));
    EXPECT_EQ(dispatch.samples_done(), samples.size() - failed.size());
}

TEST(ChunkDispatch, StopEndsTheLocalThreadAfterItsChunkAndStopsEveryRank) {
    const SampleRange samples{0, 64};
    std::promise<SampleRange> started;
    std::promise<void> release;
    std::shared_future<void> released = release.get_future().share();
    int calls = 0;  // the local thread's alone until finish_local
    ChunkDispatch dispatch(samples, 3, true, [&](SampleRange r) {
        if (calls++ == 0) {
            started.set_value(r);
            released.wait();
        }
    });
    const SampleRange first = started.get_future().get();
    const SampleRange remote_chunk = dispatch.answer(1, {0, 0});
    EXPECT_GT(remote_chunk.size(), 0u);
    dispatch.stop();  // as a failure of the dispatcher's messages does, through ~ChunkDispatch
    release.set_value();
    const std::vector<SampleRange> local = dispatch.finish_local();
    ASSERT_EQ(local.size(), 1u);
    EXPECT_EQ(local[0].begin, first.begin);
    EXPECT_EQ(calls, 1);
    EXPECT_EQ(dispatch.answer(1, remote_chunk).size(), 0u);
    EXPECT_EQ(dispatch.answer(2, {0, 0}).size(), 0u);
    EXPECT_FALSE(dispatch.remote_ranks_working());
    EXPECT_EQ(dispatch.samples_done(), first.size() + remote_chunk.size());
}

TEST(ChunkDispatch, DestroyingItMidRenderWaitsOnlyForTheLocalChunk) {
    const SampleRange samples{0, 1000};
    std::promise<void> started;
    std::promise<void> release;
    std::shared_future<void> released = release.get_future().share();
    int calls = 0;
    {
        ChunkDispatch dispatch(samples, 2, true, [&](SampleRange) {
            if (calls++ == 0) {
                started.set_value();
                released.wait();
            }
        });
        started.get_future().wait();
        dispatch.stop();
        release.set_value();
    }
    EXPECT_EQ(calls, 1);
}

TEST(ChunkDispatch, CoverageNamesTheRankOfAGapOrOverlap) {
    const SampleRange samples{0, 12};
    EXPECT_NO_THROW(check_coverage({{2, {{8, 12}}}, {0, {{4, 8}, {0, 4}}}}, samples));
    const auto message = [&](const std::vector<RankRanges>& all) {
        try {
            check_coverage(all, samples);
        } catch (const std::runtime_error& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    EXPECT_NE(message({{0, {{0, 4}}}, {1, {{6, 12}}}}).find("rank 1 has 6:12 after sample 4"), std::string::npos);
    EXPECT_NE(message({{0, {{0, 6}}}, {2, {{4, 12}}}}).find("rank 2 has 4:12 after sample 6"), std::string::npos);
    EXPECT_NE(message({{0, {{0, 4}}}, {1, {{4, 8}}}}).find("end at sample 8 of 12"), std::string::npos);
    EXPECT_NE(message({}).find("end at sample 0 of 12"), std::string::npos);
}

TEST(ChunkDispatch, ChunksAreAboutFourPerRankAndNeverEmpty) {
    EXPECT_EQ(chunk_size({0, 64}, 2), 8u);
    EXPECT_EQ(chunk_size({0, 1000}, 3), 83u);
    EXPECT_EQ(chunk_size({0, 3}, 4), 1u);
    EXPECT_EQ(chunk_size({10, 11}, 2), 1u);
}

}  // namespace
}  // namespace wt
