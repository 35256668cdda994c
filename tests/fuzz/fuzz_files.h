#pragma once
// A fuzz input that holds several files, so that libFuzzer mutates the files a mesh file names
// (an OBJ's MTL files and textures, a glTF's .bin buffers and images) along with it.
//
// The input is the main file's bytes, then any number of side files, each after a line
// "@file NAME": the separator is "\n@file NAME\n", and a file's bytes run to the next separator
// or the end. NAME is 1 to 64 of [A-Za-z0-9._-], not starting with a dot, so a side file lands in
// the input's own directory and nowhere else; a side file with another name is dropped, as is
// any past the 8th. A later file of the same name replaces an earlier one.
// tests/fuzz/pack_files.py writes such inputs from real files (the seed corpora).

#include <dirent.h>
#include <stdlib.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

namespace wt::fuzz {

struct FuzzFile {
    std::string name;
    std::string_view bytes;
};

inline bool is_side_file_name(std::string_view name) {
    if (name.empty() || name.size() > 64 || name[0] == '.') return false;
    for (const char c : name) {
        const bool plain = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '.' ||
                           c == '_' || c == '-';
        if (!plain) return false;
    }
    return true;
}

// The main file (named `main_name`) first, then the side files in input order.
inline std::vector<FuzzFile> split_fuzz_files(std::string_view input, const std::string& main_name) {
    constexpr std::string_view separator = "\n@file ";
    constexpr std::size_t max_side_files = 8;
    std::vector<FuzzFile> files;
    std::size_t at = input.find(separator);
    files.push_back({main_name, input.substr(0, at)});
    while (at != std::string_view::npos) {
        const std::size_t name_begin = at + separator.size();
        const std::size_t name_end = input.find('\n', name_begin);
        if (name_end == std::string_view::npos) break;
        const std::string_view name = input.substr(name_begin, name_end - name_begin);
        at = input.find(separator, name_end);
        const std::string_view bytes =
            input.substr(name_end + 1, at == std::string_view::npos ? std::string_view::npos : at - name_end - 1);
        if (files.size() > max_side_files || !is_side_file_name(name) || name == main_name) continue;
        files.push_back({std::string(name), bytes});
    }
    return files;
}

// A directory of its own for the process (several fuzzers run at once), emptied and refilled
// for every input, removed at exit. Made under $TMPDIR (else /tmp): a fuzzer that crashes or is
// killed never reaches the destructor, and run_fuzzers.sh points TMPDIR into the scratch
// directory it removes whatever the fuzzer's end.
class FuzzDirectory {
public:
    FuzzDirectory() {
        const char* tmp = std::getenv("TMPDIR");
        std::string name = std::string(tmp && *tmp ? tmp : "/tmp") + "/wavetrace-fuzz-XXXXXX";
        if (mkdtemp(name.data())) path_ = name;
    }
    ~FuzzDirectory() {
        clear();
        if (!path_.empty()) rmdir(path_.c_str());
    }
    const std::string& path() const { return path_; }

    // False if the directory or a file could not be written (the input is then skipped).
    bool hold(const std::vector<FuzzFile>& files) {
        if (path_.empty()) return false;
        clear();
        for (const FuzzFile& f : files) {
            std::FILE* out = std::fopen((path_ + "/" + f.name).c_str(), "wb");
            if (!out) return false;
            const bool written = std::fwrite(f.bytes.data(), 1, f.bytes.size(), out) == f.bytes.size();
            if (std::fclose(out) != 0 || !written) return false;
        }
        return true;
    }

private:
    // Every file, not only the last input's: a reader could have left one (none does today).
    void clear() {
        if (path_.empty()) return;
        DIR* dir = opendir(path_.c_str());
        if (!dir) return;
        std::vector<std::string> names;
        while (const dirent* e = readdir(dir))
            if (std::string_view(e->d_name) != "." && std::string_view(e->d_name) != "..") names.push_back(e->d_name);
        closedir(dir);
        for (const std::string& n : names) unlink((path_ + "/" + n).c_str());
    }

    std::string path_;
};

}  // namespace wt::fuzz
