#pragma once
// How the shade kernels' queues are sized. The kernels (kernels/shading) load whole aligned
// vectors of up to 16 lanes, so a queue allocates its entries rounded up to whole vectors, and
// one vector more; what the lanes past `count` hold is computed and thrown away.

#include <cstddef>

namespace wt {

constexpr std::size_t kKernelPadding = 16;

// The entries to allocate for a queue of `n`.
constexpr std::size_t padded_entries(std::size_t n) {
    return (n + 2 * kKernelPadding - 1) / kKernelPadding * kKernelPadding;
}

}  // namespace wt
