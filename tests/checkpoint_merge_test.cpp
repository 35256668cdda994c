// Merging partial renders: the same bits in any order, and every overlap, gap or mismatch
// named with its files.

#include <unistd.h>

#include <algorithm>
#include <filesystem>

#include <gtest/gtest.h>

#include "core/checkpoint/checkpoint_merge.h"
#include "core/system/version.h"

namespace wt {
namespace {

namespace fs = std::filesystem;

struct Merge : ::testing::Test {
    fs::path dir = fs::temp_directory_path() / ("wt_merge_" + std::to_string(getpid()));
    RenderSettings settings;
    void SetUp() override { fs::create_directories(dir); }
    void TearDown() override { fs::remove_all(dir); }

    // Samples [first, next) of a 3x2 film: sample s of pixel p has radiance (p + 1) * 0.1 * (s + 1).
    static Film film_of(uint32_t first, uint32_t next) {
        Film film(3, 2);
        for (uint32_t p = 0; p < 6; ++p)
            for (uint32_t s = first; s < next; ++s) film.add_sample(p, glm::vec3(float(p + 1) * 0.1f * float(s + 1)));
        return film;
    }
    std::string part(uint32_t first, uint32_t next, const std::string& name, uint64_t hash = 42) {
        const std::string path = (dir / name).string();
        write_checkpoint_file(path, {program_version(), hash, first, next, next, image_settings(settings)}, film_of(first, next));
        return path;
    }
    static std::string refusal(const std::vector<std::string>& paths) {
        try {
            merge_checkpoint_files(paths);
        } catch (const CheckpointError& e) {
            return e.what();
        }
        ADD_FAILURE() << "merged";
        return "";
    }
};

TEST_F(Merge, AnAdaptiveRenderIsNotMergedWithOtherParts) {
    settings.adaptive.threshold = 0.1f;
    Film adaptive = film_of(0, 4);
    adaptive.adaptive().stopped_at.assign(6, AdaptiveState::still_sampling);
    adaptive.adaptive().next_sample = 4;
    const std::string path = (dir / "adaptive.ckpt").string();
    write_checkpoint_file(path, {program_version(), 42, 0, 4, 4, image_settings(settings)}, adaptive);
    const std::string other = part(4, 6, "other.ckpt");
    EXPECT_EQ(refusal({path, other}), path + " is a render with adaptive sampling, which cannot be merged with other parts");
    // Alone it is its own merge, state and all.
    EXPECT_TRUE(merge_checkpoint_files({path}).merged.film == adaptive);
}

TEST_F(Merge, AnyOrderGivesTheFilmOfAllSamples) {
    std::vector<std::string> parts = {part(0, 3, "a.ckpt"), part(3, 4, "b.ckpt"), part(4, 9, "c.ckpt"), part(9, 9, "empty.ckpt")};
    const Film whole = film_of(0, 9);
    std::sort(parts.begin(), parts.end());
    do {
        const MergedCheckpoint m = merge_checkpoint_files(parts);
        EXPECT_TRUE(m.merged.film == whole);
        EXPECT_TRUE(m.gaps.empty());
        EXPECT_EQ(m.merged.header.first_sample, 0u);
        EXPECT_EQ(m.merged.header.next_sample, 9u);
        EXPECT_EQ(m.merged.header.target_sample, 9u);
    } while (std::next_permutation(parts.begin(), parts.end()));
}

TEST_F(Merge, GapsAreReported) {
    const MergedCheckpoint m = merge_checkpoint_files({part(8, 9, "c.ckpt"), part(2, 3, "a.ckpt"), part(5, 6, "b.ckpt")});
    ASSERT_EQ(m.gaps.size(), 2u);
    EXPECT_EQ(m.gaps[0].begin, 3u);
    EXPECT_EQ(m.gaps[0].end, 5u);
    EXPECT_EQ(m.gaps[1].begin, 6u);
    EXPECT_EQ(m.gaps[1].end, 8u);
    EXPECT_EQ(m.merged.header.first_sample, 2u);
    EXPECT_EQ(m.merged.header.next_sample, 9u);
}

TEST_F(Merge, OverlapsAreRefusedNamingBothFiles) {
    const std::string a = part(0, 4, "a.ckpt"), b = part(3, 6, "b.ckpt");
    const std::string expected = a + " (samples 0:4) and " + b + " (samples 3:6) overlap: samples 3:4 would be counted twice";
    EXPECT_EQ(refusal({a, b}), expected);
    EXPECT_EQ(refusal({b, a}), expected);
    EXPECT_NE(refusal({a, a}).find("samples 0:4 would be counted twice"), std::string::npos);
}

TEST_F(Merge, MismatchedPartsAreRefusedSayingWhatDiffers) {
    const std::string a = part(0, 4, "a.ckpt");
    settings.seed = 3;
    const std::string b = part(4, 6, "b.ckpt", 43);
    EXPECT_EQ(refusal({a, b}), b + " is not a part of the same render as " + a +
                                   ": scene content (camera, materials or geometry): " + a + " hash 000000000000002a, " + b +
                                   " hash 000000000000002b; seed: " + a + " 0, " + b + " 3");
    const std::string missing = (dir / "missing.ckpt").string();
    EXPECT_EQ(refusal({a, missing}), missing + ": cannot open: No such file or directory");
}

}  // namespace
}  // namespace wt
