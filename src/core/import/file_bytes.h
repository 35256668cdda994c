#pragma once
// A file read front to back through one fixed buffer, knowing the offset of every byte it hands
// out: mesh files can be gigabytes, and a message should say where a problem is.

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

namespace wt {

class FileBytes {
public:
    // Throws MeshFileError if the file cannot be opened.
    explicit FileBytes(const std::string& path);

    // Copies the next n bytes to out; false (and nothing consumed) at the end of the file.
    // Inline for the buffered case: a binary mesh is millions of reads of a few bytes, and with
    // a constant n the copy is one load.
    bool read(void* out, std::size_t n) {
        if (end_ - pos_ < n) return read_across_refill(out, n);
        std::memcpy(out, buffer_.data() + pos_, n);
        pos_ += n;
        return true;
    }
    // The next line without its "\n" or "\r\n"; false at the end of the file.
    bool read_line(std::string& line);
    // Offset of the next byte to be read.
    uint64_t offset() const { return consumed_ + pos_; }
    uint64_t size() const { return size_; }

private:
    bool refill();  // keeps the unread bytes, appends more; false if nothing more was read
    bool read_across_refill(void* out, std::size_t n);

    std::string path_;
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> file_;
    std::vector<char> buffer_;
    std::size_t pos_ = 0, end_ = 0;  // unread bytes are buffer_[pos_, end_)
    uint64_t consumed_ = 0;          // file offset of buffer_[0]
    uint64_t size_ = 0;
};

}  // namespace wt
