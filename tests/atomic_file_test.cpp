// write_file_atomically: the target holds the old file or the new one, never part of one.

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <gtest/gtest.h>

#include "core/system/atomic_file.h"

namespace wt {
namespace {

namespace fs = std::filesystem;

std::string read_all(const fs::path& p) {
    std::ifstream in(p);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

void write_text(const std::string& path, const std::string& text) {
    std::ofstream out(path);
    out << text;
    if (!out.flush()) throw std::runtime_error("cannot write " + path);
}

struct AtomicFile : ::testing::Test {
    fs::path dir = fs::temp_directory_path() / ("wt_atomic_" + std::to_string(getpid()));
    void SetUp() override { fs::create_directories(dir); }
    void TearDown() override {
        fs::permissions(dir, fs::perms::owner_all, fs::perm_options::add);
        fs::remove_all(dir);
    }
    std::size_t entries() const { return std::size_t(std::distance(fs::directory_iterator(dir), fs::directory_iterator())); }
};

TEST_F(AtomicFile, ReplacesTheTargetAndLeavesNoTemporary) {
    const std::string target = (dir / "out.txt").string();
    write_text(target, "old");
    write_file_atomically(target, [](const std::string& tmp) {
        EXPECT_EQ(fs::path(tmp).extension(), ".txt") << "the extension stays last";
        EXPECT_STREQ(temporary_file_in_progress(), tmp.c_str());
        write_text(tmp, "new");
    });
    EXPECT_EQ(read_all(target), "new");
    EXPECT_EQ(entries(), 1u);
    EXPECT_STREQ(temporary_file_in_progress(), "");
}

TEST_F(AtomicFile, AFailedWriteKeepsThePreviousFileAndRemovesTheTemporary) {
    const std::string target = (dir / "out.txt").string();
    write_text(target, "old");
    EXPECT_THROW(write_file_atomically(target,
                                       [](const std::string& tmp) {
                                           write_text(tmp, "half");
                                           throw std::runtime_error("disk full");
                                       }),
                 std::runtime_error);
    EXPECT_EQ(read_all(target), "old");
    EXPECT_EQ(entries(), 1u);
    EXPECT_STREQ(temporary_file_in_progress(), "");
}

// Root may write into read-only directories, so the directory is taken away instead: the
// same failure as an unmounted or deleted output directory during a long render.
TEST_F(AtomicFile, AVanishedDirectoryIsAnErrorAndLeavesNothing) {
    const fs::path sub = dir / "renders";
    fs::create_directories(sub);
    const std::string target = (sub / "out.txt").string();
    fs::remove_all(sub);
    EXPECT_THROW(write_file_atomically(target, [](const std::string& tmp) { write_text(tmp, "new"); }), std::runtime_error);
    EXPECT_EQ(entries(), 0u);
    EXPECT_STREQ(temporary_file_in_progress(), "");
}

}  // namespace
}  // namespace wt
