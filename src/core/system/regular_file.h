#pragma once
// Opening an input file that a user named: only a regular file, and only up to a size limit,
// checked before a byte is read. Without this, `wavetrace render /dev/zero` reads until memory
// runs out, and a FIFO blocks forever in open().

#include <cstdint>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>

namespace wt {

// Scene files are read whole and parsed into a tree several times their size.
constexpr uint64_t kMaxSceneFileBytes = uint64_t(256) << 20;  // 256 MiB
// Mesh files are streamed; the limit only stops a runaway (a 1M-triangle OBJ is 81 MB).
constexpr uint64_t kMaxMeshFileBytes = uint64_t(16) << 30;  // 16 GiB

// what() is the complete message: "PATH: cannot open: not a regular file (a FIFO)".
struct InputFileError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

struct RegularFile {
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> file{nullptr, &std::fclose};
    uint64_t size = 0;  // when it was opened
};

// Opens path for reading if it is a regular file of at most max_bytes; throws InputFileError
// naming the path otherwise. Opened without blocking, so a FIFO is refused, not waited on.
RegularFile open_regular_file(const std::string& path, uint64_t max_bytes);

// The whole file, which must not grow past max_bytes while it is read.
std::string read_regular_file(const std::string& path, uint64_t max_bytes);

}  // namespace wt
