#pragma once
// std::vector whose storage starts on a 64-byte boundary (one cache line, one AVX-512 register),
// so SoA buffers can be read with aligned vector loads by the SIMD kernels.

#include <cstddef>
#include <new>
#include <utility>
#include <vector>

namespace wt {

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

    T* allocate(std::size_t n) {
        return static_cast<T*>(::operator new(n * sizeof(T), std::align_val_t(Alignment)));
    }
    void deallocate(T* p, std::size_t) noexcept { ::operator delete(p, std::align_val_t(Alignment)); }

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
