#include "core/import/file_bytes.h"

#include <cerrno>
#include <cstring>
#include <filesystem>

#include "core/import/imported_mesh.h"

namespace wt {

FileBytes::FileBytes(const std::string& path)
    : path_(path), file_(std::fopen(path.c_str(), "rb"), &std::fclose), buffer_(std::size_t(1) << 20) {
    if (!file_) throw MeshFileError(path + ": cannot open: " + std::strerror(errno));
    std::error_code ec;
    size_ = std::filesystem::file_size(path, ec);
}

bool FileBytes::refill() {
    if (pos_ > 0) {
        std::memmove(buffer_.data(), buffer_.data() + pos_, end_ - pos_);
        consumed_ += pos_;
        end_ -= pos_;
        pos_ = 0;
    }
    if (end_ == buffer_.size()) buffer_.resize(buffer_.size() * 2);  // a line longer than the buffer
    const std::size_t n = std::fread(buffer_.data() + end_, 1, buffer_.size() - end_, file_.get());
    if (n == 0 && std::ferror(file_.get()))
        throw MeshFileError(path_ + ": byte " + std::to_string(offset()) + ": cannot read: " + std::strerror(errno));
    end_ += n;
    return n > 0;
}

bool FileBytes::read_across_refill(void* out, std::size_t n) {
    while (end_ - pos_ < n)
        if (!refill()) return false;
    std::memcpy(out, buffer_.data() + pos_, n);
    pos_ += n;
    return true;
}

bool FileBytes::read_line(std::string& line) {
    std::size_t scanned = pos_;
    for (;;) {
        const void* nl = std::memchr(buffer_.data() + scanned, '\n', end_ - scanned);
        if (nl) {
            const std::size_t at = std::size_t(static_cast<const char*>(nl) - buffer_.data());
            std::size_t stop = at;
            if (stop > pos_ && buffer_[stop - 1] == '\r') --stop;
            line.assign(buffer_.data() + pos_, stop - pos_);
            pos_ = at + 1;
            return true;
        }
        const std::size_t unread_scanned = end_ - pos_;
        if (!refill()) break;
        scanned = pos_ + unread_scanned;
    }
    if (pos_ == end_) return false;
    line.assign(buffer_.data() + pos_, end_ - pos_);  // a last line without "\n"
    if (!line.empty() && line.back() == '\r') line.pop_back();
    pos_ = end_;
    return true;
}

}  // namespace wt
