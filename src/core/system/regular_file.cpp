#include "core/system/regular_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace wt {
namespace {

const char* kind_of(mode_t mode) {
    if (S_ISDIR(mode)) return "a directory";
    if (S_ISFIFO(mode)) return "a FIFO";
    if (S_ISCHR(mode)) return "a character device";
    if (S_ISBLK(mode)) return "a block device";
    if (S_ISSOCK(mode)) return "a socket";
    return "not a regular file";
}

std::string limit_text(uint64_t bytes) {
    return bytes % (uint64_t(1) << 30) == 0 ? std::to_string(bytes >> 30) + " GiB"
                                             : std::to_string(bytes >> 20) + " MiB";
}

}  // namespace

RegularFile open_regular_file(const std::string& path, uint64_t max_bytes) {
    // O_NONBLOCK: opening a FIFO for reading would otherwise wait for a writer.
    const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) throw InputFileError(path + ": cannot open: " + std::strerror(errno));
    struct stat st {};
    if (::fstat(fd, &st) != 0) {
        const int error = errno;
        ::close(fd);
        throw InputFileError(path + ": cannot open: " + std::strerror(error));
    }
    if (!S_ISREG(st.st_mode)) {
        ::close(fd);
        throw InputFileError(path + ": cannot open: " + kind_of(st.st_mode) + ", not a regular file");
    }
    if (uint64_t(st.st_size) > max_bytes) {
        ::close(fd);
        throw InputFileError(path + ": " + std::to_string(st.st_size) + " bytes, larger than the limit of " +
                             limit_text(max_bytes) + " for this kind of file");
    }
    ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);
    RegularFile out;
    out.file.reset(::fdopen(fd, "rb"));
    if (!out.file) {
        const int error = errno;
        ::close(fd);
        throw InputFileError(path + ": cannot open: " + std::strerror(error));
    }
    out.size = uint64_t(st.st_size);
    return out;
}

std::string read_regular_file(const std::string& path, uint64_t max_bytes) {
    const RegularFile in = open_regular_file(path, max_bytes);
    std::string text;
    text.reserve(std::size_t(in.size));
    char buffer[1 << 16];
    std::size_t n;
    while ((n = std::fread(buffer, 1, sizeof buffer, in.file.get())) > 0) {
        if (text.size() + n > max_bytes)
            throw InputFileError(path + ": grew past the limit of " + limit_text(max_bytes) + " while being read");
        text.append(buffer, n);
    }
    if (std::ferror(in.file.get())) throw InputFileError(path + ": cannot read: " + std::strerror(errno));
    return text;
}

}  // namespace wt
