#pragma once
// A file mapped read-only, so its bytes are in memory once: the page cache's copy, which a
// parser reads (tinygltf copies a .glb's binary chunk out of it), rather than a heap copy too.

#include <cerrno>
#include <cstring>
#include <string>

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include "core/import/imported_mesh.h"

namespace wt {

// Throws MeshFileError naming the path if it cannot be opened or mapped.
class MappedFile {
public:
    explicit MappedFile(const std::string& path) {
        const int fd = ::open(path.c_str(), O_RDONLY);
        if (fd < 0) throw MeshFileError(path + ": cannot open: " + std::strerror(errno));
        struct stat st {};
        if (::fstat(fd, &st) == 0) size_ = std::size_t(st.st_size);
        if (size_ > 0) data_ = ::mmap(nullptr, size_, PROT_READ, MAP_PRIVATE, fd, 0);
        const int mmap_errno = errno;
        ::close(fd);
        if (data_ == MAP_FAILED) throw MeshFileError(path + ": cannot map: " + std::strerror(mmap_errno));
    }
    ~MappedFile() {
        if (data_ && data_ != MAP_FAILED) ::munmap(data_, size_);
    }
    MappedFile(const MappedFile&) = delete;
    MappedFile& operator=(const MappedFile&) = delete;
    const unsigned char* data() const { return static_cast<const unsigned char*>(data_); }
    std::size_t size() const { return size_; }

private:
    void* data_ = nullptr;
    std::size_t size_ = 0;
};

}  // namespace wt
