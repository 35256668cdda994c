#pragma once
// std::vector whose storage starts on a 64-byte boundary (one cache line, one AVX-512 register),
// so SoA buffers can be read with aligned vector loads by the SIMD kernels.

#include <sys/mman.h>

#include <cstddef>
#include <cstdint>
#include <new>
#include <utility>
#include <vector>

namespace wt {

// A buffer of 2 MiB or more is mapped on its own, on a 2 MiB boundary, and offered to the
// kernel's transparent huge pages (madvise MADV_HUGEPAGE; Debian's default is to use them only
// where asked; Embree's allocator asks the same way). A BVH of a large mesh, its leaf blocks and
// the scene's arrays span tens of megabytes that the walks read at random: in 4 KiB pages that
// is thousands of TLB entries, and as many page faults the first time each page is written; in
// 2 MiB pages, a few dozen. Mapped on its own, not taken from malloc's heap, so that the advice
// ends with the buffer: heap memory left advised would give later small allocations whole huge
// pages to fault in and zero. Where the kernel has no huge page to give, or huge pages are off,
// the buffer is ordinary pages. Under AddressSanitizer every buffer comes from operator new, so
// that its checks cover them.
inline constexpr std::size_t kHugePageBytes = std::size_t(2) << 20;

#if defined(__SANITIZE_ADDRESS__)
inline constexpr bool kMapLargeBuffers = false;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
inline constexpr bool kMapLargeBuffers = false;
#else
inline constexpr bool kMapLargeBuffers = true;
#endif
#else
inline constexpr bool kMapLargeBuffers = true;
#endif

inline std::size_t whole_huge_pages(std::size_t bytes) { return (bytes + kHugePageBytes - 1) / kHugePageBytes * kHugePageBytes; }

inline void* allocate_buffer(std::size_t bytes, std::size_t alignment) {
    if (!kMapLargeBuffers || bytes < kHugePageBytes) return ::operator new(bytes, std::align_val_t(alignment));
    const std::size_t size = whole_huge_pages(bytes);
    if (size < bytes || size + kHugePageBytes < size) throw std::bad_alloc();
    // Map a huge page more than needed, then give back what lies before the first 2 MiB boundary
    // and after the buffer's end.
    void* mapped = mmap(nullptr, size + kHugePageBytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (mapped == MAP_FAILED) throw std::bad_alloc();
    const auto start = reinterpret_cast<std::uintptr_t>(mapped);
    const std::uintptr_t aligned = (start + kHugePageBytes - 1) & ~std::uintptr_t(kHugePageBytes - 1);
    if (aligned > start) munmap(mapped, aligned - start);
    if (aligned + size < start + size + kHugePageBytes)
        munmap(reinterpret_cast<void*>(aligned + size), start + size + kHugePageBytes - (aligned + size));
    void* p = reinterpret_cast<void*>(aligned);
    madvise(p, size, MADV_HUGEPAGE);  // advice only: a refusal leaves ordinary pages
    return p;
}

inline void free_buffer(void* p, std::size_t bytes, std::size_t alignment) noexcept {
    if (!kMapLargeBuffers || bytes < kHugePageBytes) ::operator delete(p, std::align_val_t(alignment));
    else munmap(p, whole_huge_pages(bytes));
}

template <typename T, std::size_t Alignment = 64>
struct AlignedAllocator {
    using value_type = T;
    template <typename U>
    struct rebind {
        using other = AlignedAllocator<U, Alignment>;
    };

    AlignedAllocator() = default;
    template <typename U>
    AlignedAllocator(const AlignedAllocator<U, Alignment>&) noexcept {}

    T* allocate(std::size_t n) { return static_cast<T*>(allocate_buffer(n * sizeof(T), Alignment)); }
    void deallocate(T* p, std::size_t n) noexcept { free_buffer(p, n * sizeof(T), Alignment); }

    template <typename U>
    bool operator==(const AlignedAllocator<U, Alignment>&) const noexcept { return true; }
    template <typename U>
    bool operator!=(const AlignedAllocator<U, Alignment>&) const noexcept { return false; }
};

template <typename T>
using AlignedVector = std::vector<T, AlignedAllocator<T>>;

// For a large buffer every element of which is written before it is read, by parallel jobs:
// resize() leaves the new elements uninitialised instead of zeroing them on one thread, so the
// pages are first touched (faulted in) by the threads that fill them.
template <typename T, std::size_t Alignment = 64>
struct UninitialisedAllocator : AlignedAllocator<T, Alignment> {
    template <typename U>
    struct rebind {
        using other = UninitialisedAllocator<U, Alignment>;
    };
    using AlignedAllocator<T, Alignment>::AlignedAllocator;

    template <typename U>
    void construct(U* p) noexcept {
        ::new (static_cast<void*>(p)) U;  // default-initialised: no value for a float
    }
    template <typename U, typename... Args>
    void construct(U* p, Args&&... args) {
        ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
    }
};

template <typename T>
using UninitialisedVector = std::vector<T, UninitialisedAllocator<T>>;

}  // namespace wt
