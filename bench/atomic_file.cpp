#include "atomic_file.h"

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace wt::bench {

void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& write) {
    namespace fs = std::filesystem;
    const fs::path target(path);
    // A name .gitignore ignores (*.tmp-*), unique per process.
    const fs::path temporary = target.parent_path() / ("." + target.filename().string() + ".tmp-" + std::to_string(getpid()));
    std::error_code ignored;
    try {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        if (!out) throw std::runtime_error(path + ": cannot create " + temporary.string());
        write(out);
        out.flush();
        if (!out) throw std::runtime_error(path + ": writing failed (disk full?)");
    } catch (...) {
        fs::remove(temporary, ignored);
        throw;
    }
    std::error_code ec;
    fs::rename(temporary, target, ec);
    if (ec) {
        fs::remove(temporary, ignored);
        throw std::runtime_error(path + ": cannot move the finished file into place: " + ec.message());
    }
}

}  // namespace wt::bench
