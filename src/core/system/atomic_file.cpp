#include "core/system/atomic_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>

namespace wt {

namespace fs = std::filesystem;

namespace {

// A fixed buffer, not a std::string: the signal handler must read it without allocating.
char in_progress[4096];
std::atomic<bool> in_progress_set{false};

void register_temporary(const std::string& path) {
    if (path.size() >= sizeof in_progress) return;
    std::memcpy(in_progress, path.c_str(), path.size() + 1);
    in_progress_set.store(true);
}

void unregister_temporary() { in_progress_set.store(false); }

std::string temporary_path_for(const std::string& path) {
    const fs::path p(path);
    const std::string name = "." + p.stem().string() + ".tmp-" + std::to_string(getpid()) + p.extension().string();
    return (p.parent_path() / name).string();
}

void sync_path(const std::string& path, int flags, const std::string& target, const char* what) {
    const int fd = open(path.c_str(), flags | O_CLOEXEC);
    if (fd < 0) throw FileWriteError(target + ": cannot open " + what + " to sync it: " + std::strerror(errno));
    const bool ok = fsync(fd) == 0 || errno == EINVAL;  // EINVAL: a file system that cannot sync directories
    const int error = errno;
    close(fd);
    if (!ok) throw FileWriteError(target + ": cannot sync " + what + " to the disk: " + std::strerror(error));
}

}  // namespace

void write_text_file_atomically(const std::string& path, const std::string& text) {
    write_file_atomically(path, [&](const std::string& temporary) {
        std::ofstream out(temporary, std::ios::binary);
        out << text;
        out.close();
        if (!out) throw FileWriteError(path + ": writing failed");
    });
}

void check_output_directory(const std::string& path) {
    fs::path dir = fs::path(path).parent_path();
    if (dir.empty()) dir = ".";
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) throw FileWriteError(path + ": directory '" + dir.string() + "' does not exist");
    if (access(dir.c_str(), W_OK) != 0) throw FileWriteError(path + ": directory '" + dir.string() + "' is not writable");
    // Found after rendering, these cost the whole render: rename() cannot replace a directory,
    // and the temporary name is longer than the file's.
    if (fs::is_directory(path, ec)) throw FileWriteError(path + ": is a directory, cannot be replaced by a file");
    const long name_max = pathconf(dir.c_str(), _PC_NAME_MAX);
    const std::size_t limit = name_max > 0 ? std::size_t(name_max) : 255;
    const std::size_t temporary_name = fs::path(temporary_path_for(path)).filename().string().size();
    if (temporary_name > limit)
        throw FileWriteError(path + ": file name too long: the temporary file written beside it would have a " +
                             std::to_string(temporary_name) + "-byte name, more than the " + std::to_string(limit) +
                             " the directory allows");
}

const char* temporary_file_in_progress() { return in_progress_set.load() ? in_progress : ""; }

void write_file_atomically(const std::string& path, const std::function<void(const std::string&)>& write) {
    const std::string temporary = temporary_path_for(path);
    register_temporary(temporary);
    try {
        write(temporary);
        sync_path(temporary, O_RDONLY, path, "the new file");
        if (std::rename(temporary.c_str(), path.c_str()) != 0)
            throw FileWriteError(path + ": cannot move the finished file into place: " + std::strerror(errno));
    } catch (...) {
        std::remove(temporary.c_str());
        unregister_temporary();
        throw;
    }
    unregister_temporary();
    std::string dir = fs::path(path).parent_path().string();
    sync_path(dir.empty() ? "." : dir, O_RDONLY | O_DIRECTORY, path, "its directory");
}

}  // namespace wt
