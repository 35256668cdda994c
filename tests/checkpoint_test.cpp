// Checkpoint files: a film and its header come back bit for bit, and every damaged, foreign or
// absurd file is refused with a message naming the file and the problem, before any large
// allocation.

#include <signal.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>
#include <xxhash.h>

#include "core/system/atomic_file.h"
#include "core/checkpoint/checkpoint.h"
#include "core/checkpoint/checkpoint_format.h"
#include "core/checkpoint/checkpoint_match.h"
#include "core/system/version.h"
#include "checkpoint_rewrite.h"

namespace wt {
namespace {

namespace fs = std::filesystem;

CheckpointHeader test_header(uint32_t first = 0, uint32_t next = 4, uint32_t target = 8) {
    RenderSettings settings;
    settings.seed = 7;
    return {program_version(), 0x0123456789abcdefull, first, next, target, image_settings(settings)};
}

// A film whose pixels have `samples` samples each of varied magnitude, optionally one huge
// enough that its sums need the 16-byte encoding.
Film test_film(int width, int height, uint32_t samples, bool huge = false, std::vector<std::string> extra = {}) {
    Film film(width, height, extra);
    uint64_t state = 99;
    std::vector<float> extra_values(extra.size());
    for (uint32_t p = 0; p < film.pixel_total(); ++p)
        for (uint32_t s = 0; s < samples; ++s) {
            state = state * 6364136223846793005ull + 1442695040888963407ull;
            const float v = float(state >> 40) / float(1 << 24) * (s % 3 == 0 ? 0.001f : 20.0f);
            for (std::size_t c = 0; c < extra.size(); ++c) extra_values[c] = -v * float(c + 1);
            EXPECT_TRUE(film.add_sample(p, glm::vec3(v, 2 * v, huge && p == 0 ? 3e7f : v), extra_values.data()));
        }
    return film;
}

std::string expect_refused(const std::string& bytes, const std::string& name = "part.ckpt") {
    try {
        parse_checkpoint(bytes, name);
    } catch (const CheckpointError& e) {
        const std::string message = e.what();
        EXPECT_EQ(message.rfind(name + ": ", 0), 0u) << "the message names the file: " << message;
        return message;
    }
    ADD_FAILURE() << "accepted";
    return "";
}

// `bytes` with its text header replaced and the checksum made valid again: what a writer with a
// bug (or a hostile file) could produce, to test the checks behind the checksum.
std::string with_header(const std::string& bytes, const std::string& from, const std::string& to) {
    EXPECT_NE(bytes.find(from), std::string::npos) << from;
    return test::with_header_text(bytes, from, to);
}

TEST(Checkpoint, FilmAndHeaderComeBackBitForBit) {
    const Film film = test_film(5, 3, 4, true, {"albedo.R", "depth"});
    const CheckpointHeader header = test_header();
    const std::string bytes = checkpoint_bytes(header, film);
    const Checkpoint back = parse_checkpoint(bytes, "a.ckpt");
    EXPECT_TRUE(back.film == film);
    EXPECT_EQ(back.header.program_version, header.program_version);
    EXPECT_EQ(back.header.scene_hash, header.scene_hash);
    EXPECT_EQ(back.header.first_sample, 0u);
    EXPECT_EQ(back.header.next_sample, 4u);
    EXPECT_EQ(back.header.target_sample, 8u);
    EXPECT_EQ(back.header.settings, header.settings);
    // The huge blue value needs 16 bytes for its sums; red fits in 8, as do the extra channels.
    EXPECT_NE(bytes.find("channel sum.R 8\n"), std::string::npos);
    EXPECT_NE(bytes.find("channel sum.B 16\n"), std::string::npos);
    EXPECT_NE(bytes.find("channel square.B 16\n"), std::string::npos);
    EXPECT_NE(bytes.find("channel depth 8\n"), std::string::npos);
    // Negative sums (the extra channels here) keep their sign through the 8-byte encoding.
    EXPECT_LT(back.film.extra_mean(1, 1), 0.0);
}

// A film of an adaptive render at sample 4 of 8: pixel 1 stopped at 2 (with its 2 samples),
// pixel 2 at 4, the others still sampled.
Film adaptive_film(int width, int height) {
    Film film = test_film(width, height, 4);
    Film stopped = test_film(width, height, 2);
    film.raw_counts()[1] = 2;
    std::copy_n(stopped.raw_sums().begin() + 6, 6, film.raw_sums().begin() + 6);
    film.adaptive().stopped_at.assign(film.pixel_total(), AdaptiveState::still_sampling);
    film.adaptive().stopped_at[1] = 2;
    film.adaptive().stopped_at[2] = 4;
    film.adaptive().next_sample = 4;
    return film;
}

TEST(Checkpoint, EveryTruncationIsRefused) {
    for (const Film& film : {test_film(3, 2, 4), adaptive_film(3, 2)}) {
        const std::string bytes = checkpoint_bytes(test_header(), film);
        for (std::size_t n = 0; n < bytes.size(); ++n) {
            const std::string message = expect_refused(bytes.substr(0, n));
            if (n >= 24) {
                EXPECT_NE(message.find("truncated"), std::string::npos) << n << ": " << message;
            }
        }
    }
}

TEST(Checkpoint, AdaptiveStateComesBackBitForBit) {
    const Film film = adaptive_film(3, 2);
    const std::string bytes = checkpoint_bytes(test_header(), film);
    EXPECT_NE(bytes.find("adaptive_state yes\n"), std::string::npos);
    const Checkpoint back = parse_checkpoint(bytes, "a.ckpt");
    EXPECT_TRUE(back.film == film);
    EXPECT_EQ(back.film.adaptive().stopped_at[1], 2u);
    EXPECT_EQ(back.film.adaptive().next_sample, 4u);
    // Without adaptive sampling the block is absent and the film has no state.
    const std::string plain = checkpoint_bytes(test_header(), test_film(3, 2, 4));
    EXPECT_NE(plain.find("adaptive_state no\n"), std::string::npos);
    EXPECT_EQ(bytes.size(), plain.size() + 6 * 4 + 1);  // a u32 per pixel, "yes" one byte longer than "no"
    EXPECT_TRUE(parse_checkpoint(plain, "b.ckpt").film.adaptive().empty());
    // Every flipped bit of the block is caught.
    for (std::size_t i = bytes.size() - 8 - 24; i < bytes.size() - 8; ++i) {
        std::string damaged = bytes;
        damaged[i] ^= 4;
        expect_refused(damaged);
    }
}

// The block's claims are checked, also behind the checksum (the test re-checksums the file).
TEST(Checkpoint, ImpossibleAdaptiveStatesAreRefused) {
    const Film film = adaptive_film(3, 2);
    const std::string bytes = checkpoint_bytes(test_header(), film);
    const auto with_stop = [&](std::size_t pixel, uint32_t stop) {
        std::string out = bytes.substr(0, bytes.size() - 8);
        checkpoint_format::put_u32(reinterpret_cast<unsigned char*>(&out[out.size() - 24 + 4 * pixel]), stop);
        unsigned char sum[8];
        checkpoint_format::put_u64(sum, XXH3_64bits(out.data(), out.size()));
        return out.append(reinterpret_cast<char*>(sum), 8);
    };
    EXPECT_NE(expect_refused(with_stop(0, 5)).find("pixel (0, 0) stopped at sample 5, after the file's next sample 4"),
              std::string::npos);
    EXPECT_NE(expect_refused(with_stop(2, 3)).find("pixel (2, 0) has 4 samples but stopped at sample 3"),
              std::string::npos);
    EXPECT_TRUE(parse_checkpoint(with_stop(0, 4), "ok.ckpt").film.adaptive().stopped_at[0] == 4u);
    EXPECT_NE(expect_refused(with_header(bytes, "adaptive_state yes", "adaptive_state maybe"))
                  .find("adaptive_state must be yes or no, got 'maybe'"),
              std::string::npos);
    EXPECT_NE(expect_refused(with_header(bytes, "samples 0 4 8", "samples 1 4 8"))
                  .find("an adaptive render's checkpoint starts at sample 0, this one at 1"),
              std::string::npos);
    // "no" with the block there: the header describes a shorter file.
    EXPECT_NE(expect_refused(with_header(bytes, "adaptive_state yes", "adaptive_state no")).find("data after the end"),
              std::string::npos);
}

TEST(Checkpoint, TheWriterRefusesAStateOfOtherSamples) {
    const Film film = adaptive_film(3, 2);  // at sample 4
    EXPECT_THROW(checkpoint_bytes(test_header(0, 5, 8), film), std::invalid_argument);
    EXPECT_THROW(checkpoint_bytes(test_header(1, 4, 8), film), std::invalid_argument);
}

// What a fuzz target sees with the checksum off: every damaged file is still refused or read
// as a film of its sizes, never a crash (run under the sanitizers by the fuzz build).
TEST(Checkpoint, BehindTheChecksumDamageIsRefusedOrReadSafely) {
    const std::string bytes = checkpoint_bytes(test_header(), test_film(2, 2, 3));
    int refused = 0;
    for (std::size_t i = 0; i + 8 < bytes.size(); ++i) {
        std::string damaged = bytes;
        damaged[i] = char(damaged[i] ^ 0x41);
        try {
            const Checkpoint c = parse_checkpoint(damaged, "fuzz.ckpt", false);
            EXPECT_EQ(c.film.pixel_total(), std::size_t(c.film.width()) * std::size_t(c.film.height()));
        } catch (const CheckpointError&) {
            ++refused;
        }
    }
    EXPECT_GT(refused, 0);
    EXPECT_TRUE(parse_checkpoint(bytes, "fuzz.ckpt", false).film == test_film(2, 2, 3));
}

TEST(Checkpoint, EveryFlippedBitIsRefused) {
    const std::string bytes = checkpoint_bytes(test_header(), test_film(2, 2, 3));
    for (std::size_t i = 0; i < bytes.size(); ++i)
        for (int bit = 0; bit < 8; ++bit) {
            std::string damaged = bytes;
            damaged[i] = char(damaged[i] ^ (1 << bit));
            expect_refused(damaged);
        }
    std::string damaged = bytes;
    damaged[bytes.size() / 2] ^= 1;
    EXPECT_NE(expect_refused(damaged).find("checksum mismatch"), std::string::npos);
}

TEST(Checkpoint, ForeignFilesAreNamedForWhatTheyAre) {
    const std::string bytes = checkpoint_bytes(test_header(), test_film(2, 2, 3));
    EXPECT_NE(expect_refused("P6\n2 2\n255\n............").find("not a wavetrace checkpoint"), std::string::npos);
    std::string version1 = bytes, version3 = bytes;
    version1[8] = 1;
    version3[8] = 3;
    EXPECT_NE(expect_refused(version1).find("byte 8: checkpoint format version 1, this program reads version 2 (version 2 "
                                            "added adaptive sampling's per-pixel state): resume or merge it with the "
                                            "wavetrace that wrote it"),
              std::string::npos);
    EXPECT_NE(expect_refused(version3).find("byte 8: checkpoint format version 3, this program reads version 2"),
              std::string::npos);
    CheckpointHeader old = test_header();
    old.program_version = "0.0.1";
    EXPECT_NE(expect_refused(checkpoint_bytes(old, test_film(2, 2, 3))).find("written by wavetrace 0.0.1, this is wavetrace"),
              std::string::npos);
}

TEST(Checkpoint, AbsurdSizesAreRefusedBeforeAllocating) {
    const std::string bytes = checkpoint_bytes(test_header(), test_film(2, 2, 3));
    std::string long_header = bytes;
    checkpoint_format::put_u32(reinterpret_cast<unsigned char*>(&long_header[12]), 0xffffffffu);
    EXPECT_NE(expect_refused(long_header).find("byte 12: header length 4294967295"), std::string::npos);

    struct Case {
        const char *from, *to, *expected;
    };
    const std::string line2 = "byte " + std::to_string(16 + std::strlen("program_version \n") + std::strlen(program_version()));
    const std::string bad_key = line2 + ": expected 'scene_hash HEX'";
    const Case cases[] = {
        // 65536 x 65536 pixels would be 400 GB of film: refused against the file's 400-odd bytes.
        {"film 2 2", "film 65536 65536", "truncated: the header describes"},
        {"film 2 2", "film 65537 1", "not two integers from 1 to 65536"},
        {"film 2 2", "film 0 2", "film size"},
        // A pixel claiming more samples than the range: the counts are checked too.
        {"samples 0 4 8", "samples 0 2 8", "has 3 samples, more than the 2"},
        {"samples 0 4 8", "samples 5 4 8", "is not FIRST <= NEXT <= TARGET"},
        {"samples 0 4 8", "samples 0 4 99999999999", "target sample"},
        {"channel sum.R 8", "channel sum.R 12", "8 or 16 expected"},
        {"channel sum.G", "channel albedo", "channel 1 must be sum.G"},
        {"setting seed 7", "setting seed 7\nsetting seed 8", "given twice"},
        {"scene_hash ", "scene-hash ", bad_key.c_str()},
    };
    for (const Case& c : cases)
        EXPECT_NE(expect_refused(with_header(bytes, c.from, c.to)).find(c.expected), std::string::npos) << c.to;
}

TEST(Checkpoint, DifferencesAreNamed) {
    RenderSettings a_settings, b_settings;
    a_settings.seed = 7, b_settings.seed = 8;
    b_settings.accuracy.fresnel = FresnelModel::exact;
    CheckpointHeader a = test_header(), b = test_header();
    a.settings = image_settings(a_settings), b.settings = image_settings(b_settings);
    b.scene_hash ^= 1;
    const std::vector<std::string> lines =
        checkpoint_differences(a, {4, 4, {}}, "checkpoint", b, {4, 2, {"depth"}}, "scene");
    ASSERT_EQ(lines.size(), 5u);
    EXPECT_EQ(lines[0].rfind("scene content (camera, materials or geometry): checkpoint hash 0123456789abcdef, scene hash 0123456789abcdee", 0), 0u);
    EXPECT_EQ(lines[1], "size: checkpoint 4x4, scene 4x2");
    EXPECT_EQ(lines[2], "extra channels: checkpoint (none), scene depth");
    EXPECT_EQ(lines[3], "seed: checkpoint 7, scene 8");
    EXPECT_EQ(lines[4], "fresnel: checkpoint schlick, scene exact");
    EXPECT_TRUE(checkpoint_differences(a, {4, 4, {}}, "x", a, {4, 4, {}}, "y").empty());
}

std::string setting(const RenderSettings& s, const std::string& name) {
    for (const NamedSetting& n : image_settings(s))
        if (n.name == name) return n.value;
    return "(absent)";
}

TEST(Checkpoint, EstimatorSettingsAreStoredExactlyAndSppIsNot) {
    RenderSettings s;
    EXPECT_EQ(setting(s, "sampler"), "stratified");
    EXPECT_EQ(setting(s, "spp"), "(absent)") << "spp is the sample range, which a resume may extend";
    s.estimator.sampler = SamplerKind::sobol;
    s.estimator.light_sampling = LightSampling::mis;
    EXPECT_EQ(setting(s, "sampler"), "sobol");
    EXPECT_EQ(setting(s, "light_sampling"), "mis");
    s.estimator.clamp_indirect = 0.1f;
    EXPECT_EQ(setting(s, "clamp_indirect"), "0.100000001");
}

TEST(Checkpoint, AdaptiveSettingsAreImageSettings) {
    RenderSettings s;
    EXPECT_EQ(setting(s, "adaptive_threshold"), "0");
    EXPECT_EQ(setting(s, "adaptive_min_spp"), "(absent)") << "changes nothing while adaptive sampling is off";
    RenderSettings a = s;
    a.adaptive.threshold = 0.05f;
    EXPECT_EQ(setting(a, "adaptive_threshold"), "0.0500000007");
    EXPECT_EQ(setting(a, "adaptive_min_spp"), "16");
    RenderSettings b = a;
    b.adaptive.threshold = 0.1f;
    b.adaptive.min_spp = 32;
    CheckpointHeader ha = test_header(), hb = test_header();
    ha.settings = image_settings(a), hb.settings = image_settings(b);
    const std::vector<std::string> lines = checkpoint_differences(ha, {4, 4, {}}, "checkpoint", hb, {4, 4, {}}, "this render");
    ASSERT_EQ(lines.size(), 2u);
    EXPECT_EQ(lines[0], "adaptive_threshold: checkpoint 0.0500000007, this render 0.100000001");
    EXPECT_EQ(lines[1], "adaptive_min_spp: checkpoint 16, this render 32");
}

// The fuzz target's seeds (tests/fuzz/corpus/fuzz_checkpoint) are checkpoints this reader
// accepts, so the fuzzer starts from the decoder's far end after every format change; one has
// adaptive state.
// The seeds carry the version that wrote them; the fuzz target gives them this program's
// (checkpoint_rewrite.h), so they reach the film's decoder whatever version wrote them.
TEST(Checkpoint, TheFuzzSeedsAreValidCheckpointsOfAnyVersion) {
    const fs::path corpus = fs::path(WT_SCENES_DIR) / ".." / "tests" / "fuzz" / "corpus" / "fuzz_checkpoint";
    int seeds = 0, adaptive = 0;
    for (const fs::directory_entry& e : fs::directory_iterator(corpus)) {
        std::ifstream in(e.path(), std::ios::binary);
        const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        const std::string name = e.path().string();
        const Checkpoint c = parse_checkpoint(test::with_this_program_version(bytes), name);
        ++seeds;
        adaptive += !c.film.adaptive().empty();
        // Of another version, a seed is refused as it is and read once rewritten.
        const std::string other = test::with_header_text(test::with_this_program_version(bytes),
                                                         std::string("program_version ") + program_version() + "\n",
                                                         "program_version 0.0.1-other\n");
        EXPECT_THROW(parse_checkpoint(other, name), CheckpointError) << name;
        EXPECT_NO_THROW(parse_checkpoint(test::with_this_program_version(other), name)) << name;
    }
    EXPECT_GE(seeds, 3);
    EXPECT_EQ(adaptive, 1);
}

struct CheckpointFile : ::testing::Test {
    fs::path dir = fs::temp_directory_path() / ("wt_checkpoint_" + std::to_string(getpid()));
    void SetUp() override { fs::create_directories(dir); }
    void TearDown() override { fs::remove_all(dir); }
    std::size_t entries() const { return std::size_t(std::distance(fs::directory_iterator(dir), fs::directory_iterator())); }
};

TEST_F(CheckpointFile, WrittenAtomicallyAndReadBack) {
    const std::string path = (dir / "a.ckpt").string();
    const Film film = test_film(7, 5, 3);
    write_checkpoint_file(path, test_header(), film);
    EXPECT_TRUE(read_checkpoint_file(path).film == film);
    EXPECT_EQ(entries(), 1u);
    EXPECT_TRUE(is_checkpoint_path(path));
    EXPECT_FALSE(is_checkpoint_path((dir / "a.exr").string()));
    const std::string missing = (dir / "missing.ckpt").string();
    try {
        read_checkpoint_file(missing);
        ADD_FAILURE();
    } catch (const CheckpointError& e) {
        EXPECT_EQ(std::string(e.what()), missing + ": cannot open: No such file or directory");
    }
}

// A file size limit fails the write() part-way, as a full disk does (EFBIG instead of ENOSPC):
// the previous checkpoint must stay whole and no temporary remain.
TEST_F(CheckpointFile, AFullDiskKeepsThePreviousCheckpoint) {
    const std::string path = (dir / "a.ckpt").string();
    const Film small = test_film(2, 2, 3);
    write_checkpoint_file(path, test_header(), small);
    const Film big = test_film(64, 64, 1);  // about 200 kB

    struct sigaction ignore {}, previous{};
    ignore.sa_handler = SIG_IGN;
    sigaction(SIGXFSZ, &ignore, &previous);
    rlimit old_limit{};
    getrlimit(RLIMIT_FSIZE, &old_limit);
    rlimit limit = old_limit;
    limit.rlim_cur = 50000;
    setrlimit(RLIMIT_FSIZE, &limit);
    std::string message;
    try {
        write_checkpoint_file(path, test_header(), big);
    } catch (const FileWriteError& e) {
        message = e.what();
    }
    setrlimit(RLIMIT_FSIZE, &old_limit);
    sigaction(SIGXFSZ, &previous, nullptr);

    EXPECT_EQ(message.rfind(path + ": cannot write: ", 0), 0u) << message;
    EXPECT_TRUE(read_checkpoint_file(path).film == small);
    EXPECT_EQ(entries(), 1u);
}

}  // namespace
}  // namespace wt
