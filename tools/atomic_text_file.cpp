#include "atomic_text_file.h"

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace wt {

namespace fs = std::filesystem;

void check_text_output_path(const std::string& path) {
    fs::path dir = fs::path(path).parent_path();
    if (dir.empty()) dir = ".";
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) throw std::runtime_error(path + ": directory '" + dir.string() + "' does not exist");
    if (access(dir.c_str(), W_OK) != 0) throw std::runtime_error(path + ": directory '" + dir.string() + "' is not writable");
}

void write_text_file_atomically(const std::string& path, const std::string& text) {
    const fs::path p(path);
    const std::string temporary = (p.parent_path() / ("." + p.filename().string() + ".tmp-" + std::to_string(getpid()))).string();
    {
        std::ofstream out(temporary, std::ios::binary);
        out << text;
        out.close();
        if (!out) {
            std::remove(temporary.c_str());
            throw std::runtime_error(path + ": writing failed");
        }
    }
    std::error_code ec;
    fs::rename(temporary, path, ec);
    if (ec) {
        std::remove(temporary.c_str());
        throw std::runtime_error(path + ": cannot replace it: " + ec.message());
    }
}

}  // namespace wt
