// The buffers of AlignedVector (core/base/aligned_vector.h): a small one on a 64-byte boundary
// from operator new, a large one mapped on its own on a 2 MiB boundary (but under
// AddressSanitizer), and either kind keeping its elements as the vector grows across the
// threshold and shrinks back.

#include <cstdint>
#include <numeric>

#include <gtest/gtest.h>

#include "core/base/aligned_vector.h"

namespace wt {
namespace {

std::uintptr_t address_of(const void* p) { return reinterpret_cast<std::uintptr_t>(p); }

TEST(AlignedVector, ASmallBufferIsOnACacheLineALargeOneOnAHugePage) {
    const std::size_t large = kHugePageBytes / sizeof(float);  // exactly the threshold
    AlignedVector<float> small(large - 1), big(large);
    EXPECT_EQ(address_of(small.data()) % 64, 0u);
    EXPECT_EQ(address_of(big.data()) % 64, 0u);
    if (kMapLargeBuffers) {
        EXPECT_EQ(address_of(big.data()) % kHugePageBytes, 0u);
    }
    // The small one is not forced onto a huge page: of many, at most a few could fall on one
    // by chance.
    std::vector<AlignedVector<float>> smalls(8, AlignedVector<float>(1000));
    int on_boundary = 0;
    for (const auto& v : smalls) on_boundary += address_of(v.data()) % kHugePageBytes == 0;
    EXPECT_LT(on_boundary, 8);
}

TEST(AlignedVector, ElementsSurviveGrowthAcrossTheThresholdAndBack) {
    AlignedVector<uint32_t> v;
    const std::size_t n = 3 * kHugePageBytes / sizeof(uint32_t) + 12345;  // not whole huge pages
    for (std::size_t i = 0; i < n; ++i) v.push_back(uint32_t(i * 2654435761u));
    for (std::size_t i = 0; i < n; i += 997) ASSERT_EQ(v[i], uint32_t(i * 2654435761u)) << i;
    EXPECT_EQ(v.back(), uint32_t((n - 1) * 2654435761u));  // the last element, in the last partial page
    v.resize(100);
    v.shrink_to_fit();  // back to operator new
    for (std::size_t i = 0; i < 100; ++i) ASSERT_EQ(v[i], uint32_t(i * 2654435761u)) << i;
    UninitialisedVector<float> u;
    u.resize(kHugePageBytes);  // 8 MiB, uninitialised, mapped
    std::iota(u.begin(), u.end(), 0.0f);
    EXPECT_EQ(u[kHugePageBytes - 1], float(kHugePageBytes - 1));
}

}  // namespace
}  // namespace wt
