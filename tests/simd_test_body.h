#pragma once
// The src/simd tests, written once and compiled into three TUs with different target flags
// (simd_test_sse4.cpp, simd_test_avx2.cpp, simd_test_avx512.cpp); each instantiates the
// widths its flags allow. A TU defines before including this:
//   bool tu_cpu_supported()          whether this CPU can run the TU's instructions
//   WT_SIMD_TEST_ISA_NAME            a string for the skip message
// and then instantiates the two suites (SimdWidth over its widths, ScalarReference over
// Width<1>) with a prefix naming the ISA.
//
// The oracle is width 1 (simd1_scalar.h) applied lane by lane; width 1 itself is checked
// against hand-written expectations in ScalarReference. Exactly rounded operations must match
// bit for bit (NaN payloads excepted where the hardware does not define them); rcp_fast /
// rsqrt_fast are held to a stated ULP bound.

#include <gtest/gtest.h>
#include <sys/mman.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <type_traits>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "simd/simd.h"

namespace {

using namespace wt::simd;

// ---------------------------------------------------------------------------------------------
// Width tags for the typed tests

template <int W>
struct Width {
    static constexpr int N = W;
    using F = vfloat<W>;
    using I = vint<W>;
    using B = vbool<W>;
};

struct WidthName {
    template <typename T>
    static std::string GetName(int) {
        return "w" + std::to_string(T::N);
    }
};

// ---------------------------------------------------------------------------------------------
// Values

constexpr float kInf = std::numeric_limits<float>::infinity();

float bits_to_float(uint32_t u) { return asFloat(static_cast<int32_t>(u)); }
uint32_t float_to_bits(float f) { return static_cast<uint32_t>(asInt(f)); }

// The values every binary operation is tried on in all pairs.
std::vector<float> edge_values() {
    return {
        0.0f, -0.0f, kInf, -kInf,
        bits_to_float(0x7fc00000u),  // quiet NaN
        bits_to_float(0xffc00000u),  // negative quiet NaN (x86 "default NaN")
        bits_to_float(0x7fc12345u),  // NaN with payload
        bits_to_float(0x7f800001u),  // signalling NaN
        bits_to_float(0x00000001u), bits_to_float(0x80000001u),  // smallest denormals
        bits_to_float(0x007fffffu), bits_to_float(0x00400000u),  // largest / middle denormal
        std::numeric_limits<float>::min(), -std::numeric_limits<float>::min(),
        std::numeric_limits<float>::max(), -std::numeric_limits<float>::max(),
        1.0f, -1.0f, 0.5f, 2.0f, 3.0f, -7.25f, 1.5f, -2.5f, 0.49999997f,
        1e-30f, -1e30f, 1e30f, 1e-38f, 3e38f,
        16777216.0f, 16777218.0f, 4194304.5f,
        2147483648.0f, -2147483648.0f, 2147483520.0f, -2147483904.0f,
        1.0000001f, 0.99999994f, 1e-7f, 123456.789f,
    };
}

// Random floats of every kind: raw bit patterns (any exponent, NaN, inf, denormals), uniform
// values near 1, and wide-magnitude values with random sign.
std::vector<float> random_floats(std::mt19937& rng, size_t count) {
    std::uniform_int_distribution<uint32_t> bits;
    std::uniform_real_distribution<float> unit(-4.0f, 4.0f);
    std::uniform_int_distribution<int> exponent(-40, 40);
    std::vector<float> out(count);
    for (size_t i = 0; i < count; ++i) {
        switch (i % 3) {
            case 0: out[i] = bits_to_float(bits(rng)); break;
            case 1: out[i] = unit(rng); break;
            default: out[i] = std::ldexp(unit(rng), exponent(rng)); break;
        }
    }
    return out;
}

std::vector<int32_t> random_ints(std::mt19937& rng, size_t count) {
    std::uniform_int_distribution<uint32_t> bits;
    std::uniform_int_distribution<int> small(-1000, 1000);
    const std::vector<int32_t> edges = {0, 1, -1, 2, -2, 7, 31, 32, 65535, 65536, -65536, 1 << 24, (1 << 24) + 1,
                                        INT32_MIN, INT32_MAX, INT32_MIN + 1, INT32_MAX - 1};
    std::vector<int32_t> out(edges);
    for (size_t i = edges.size(); i < count; ++i)
        out.push_back(i % 2 ? static_cast<int32_t>(bits(rng)) : small(rng));
    return out;
}

// Operands for binary / ternary float ops: all pairs of edge values (the third operand
// cycling through them), then `randoms` random triples, padded to a multiple of 16.
struct FloatOperands {
    std::vector<float> a, b, c;
};

FloatOperands float_operands(uint32_t seed, size_t randoms = 6000) {
    FloatOperands ops;
    const std::vector<float> edges = edge_values();
    const size_t e = edges.size();
    for (size_t i = 0; i < e; ++i)
        for (size_t j = 0; j < e; ++j) {
            ops.a.push_back(edges[i]);
            ops.b.push_back(edges[j]);
            ops.c.push_back(edges[(i * 7 + j * 3) % e]);
        }
    std::mt19937 rng(seed);
    const std::vector<float> ra = random_floats(rng, randoms), rb = random_floats(rng, randoms),
                             rc = random_floats(rng, randoms);
    ops.a.insert(ops.a.end(), ra.begin(), ra.end());
    ops.b.insert(ops.b.end(), rb.begin(), rb.end());
    ops.c.insert(ops.c.end(), rc.begin(), rc.end());
    while (ops.a.size() % 16) {
        ops.a.push_back(1.0f);
        ops.b.push_back(2.0f);
        ops.c.push_back(3.0f);
    }
    return ops;
}

// ---------------------------------------------------------------------------------------------
// Comparing a vector result with width 1 applied to each lane

enum class Cmp {
    bits,   // identical bit patterns (NaN payload included)
    value,  // identical bits, or both NaN (which NaN comes out of arithmetic is not fixed:
            // x86 returns the first NaN operand, and the compiler may commute a + b)
};

bool same_value(float got, float want) {
    return float_to_bits(got) == float_to_bits(want) || (std::isnan(got) && std::isnan(want));
}
bool matches(float got, float want, Cmp cmp) {
    return cmp == Cmp::bits ? float_to_bits(got) == float_to_bits(want) : same_value(got, want);
}
bool matches(int32_t got, int32_t want, Cmp) { return got == want; }
bool matches(bool got, bool want, Cmp) { return got == want; }

// Distance in units in the last place, counting across zero (-0 and +0 are 0 apart).
int64_t ulp_distance(float a, float b) {
    auto ordered = [](float f) -> int64_t {
        const int32_t i = asInt(f);
        return i >= 0 ? int64_t{i} : -int64_t{i & INT32_MAX};
    };
    const int64_t d = ordered(a) - ordered(b);
    return d < 0 ? -d : d;
}

std::string show(float f) {
    std::ostringstream s;
    s.precision(9);
    s << f << " [0x" << std::hex << float_to_bits(f) << "]";
    return s.str();
}
std::string show(int32_t i) { return std::to_string(i); }
std::string show(bool b) { return b ? "true" : "false"; }
std::string show(vfloat<1> v) { return show(v.v); }
std::string show(vint<1> v) { return show(v.v); }
std::string show(vbool<1> v) { return show(v.v); }

// Lane i of an operand, as the width-1 type (scalars such as shift counts pass through).
template <int N>
vfloat<1> lane1(const vfloat<N>& v, int i) { return vfloat<1>(v[i]); }
template <int N>
vint<1> lane1(const vint<N>& v, int i) { return vint<1>(v[i]); }
template <int N>
vbool<1> lane1(const vbool<N>& v, int i) { return vbool<1>(v[i]); }
inline int lane1(int x, int) { return x; }

// Too many identical failures help nobody: report the first few per test.
int g_reported_failures = 0;

template <typename... Args>
std::string show_operands(const Args&... args) {
    std::string s;
    ((s += (s.empty() ? "" : ", ") + show(args)), ...);
    return s;
}

// op(args...) on the vector type, and on each lane with the width-1 types; results must match.
template <typename Op, typename... Args>
void check_lanes(const char* what, Cmp cmp, Op op, const Args&... args) {
    const auto got = op(args...);
    constexpr int n = std::decay_t<decltype(got)>::N;
    for (int i = 0; i < n; ++i) {
        const auto want = op(lane1(args, i)...);
        if (!matches(got[i], want[0], cmp)) {
            if (++g_reported_failures <= 20)
                ADD_FAILURE() << what << " lane " << i << " of " << n << ": operands (" << show_operands(lane1(args, i)...)
                              << ") got " << show(got[i]) << ", width 1 gives " << show(want[0]);
            else
                FAIL() << "further failures suppressed";
        }
    }
}

// Calls f(a, b, c) for every N-lane packet of the operand arrays.
template <typename W, typename Fn>
void for_each_packet(const FloatOperands& ops, Fn f) {
    using F = typename W::F;
    for (size_t p = 0; p + W::N <= ops.a.size(); p += W::N)
        f(F::loadu(&ops.a[p]), F::loadu(&ops.b[p]), F::loadu(&ops.c[p]));
}

template <int N>
std::array<float, N> to_array(const vfloat<N>& v) {
    std::array<float, N> out;
    vfloat<N>::storeu(out.data(), v);
    return out;
}

// Mask patterns to try: all of them up to 8 lanes, otherwise the special ones plus random.
std::vector<uint32_t> mask_patterns(int n, uint32_t seed, size_t randoms = 3000) {
    std::vector<uint32_t> out;
    if (n <= 8) {
        for (uint32_t m = 0; m < (1u << n); ++m) out.push_back(m);
        return out;
    }
    const uint32_t full = (1u << n) - 1;
    out = {0u, full, 0x5555u & full, 0xAAAAu & full, 1u, 1u << (n - 1), full >> 1, full - 1};
    for (int i = 0; i < n; ++i) out.push_back(1u << i);
    std::mt19937 rng(seed);
    std::uniform_int_distribution<uint32_t> bits(0, full);
    for (size_t i = 0; i < randoms; ++i) out.push_back(bits(rng));
    return out;
}

// ---------------------------------------------------------------------------------------------
// Memory whose end is followed by an inaccessible page: reading or writing one element past
// what an operation may touch crashes the test (which is the point).

class GuardedPage {
public:
    GuardedPage() {
        page_ = static_cast<size_t>(sysconf(_SC_PAGESIZE));
        void* p = mmap(nullptr, 2 * page_, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
        if (p == MAP_FAILED) return;
        base_ = static_cast<char*>(p);
        if (mprotect(base_ + page_, page_, PROT_NONE) != 0) {
            munmap(base_, 2 * page_);
            base_ = nullptr;
        }
    }
    ~GuardedPage() {
        if (base_) munmap(base_, 2 * page_);
    }
    GuardedPage(const GuardedPage&) = delete;
    GuardedPage& operator=(const GuardedPage&) = delete;

    bool ok() const { return base_ != nullptr; }
    // The last `count` elements of T before the guard page.
    template <typename T>
    T* last(int count) {
        return reinterpret_cast<T*>(base_ + page_) - count;
    }

private:
    char* base_ = nullptr;
    size_t page_ = 0;
};

// ---------------------------------------------------------------------------------------------
// Suite 1: every width of the TU against width 1

template <typename W>
class SimdWidth : public ::testing::Test {
protected:
    void SetUp() override {
        g_reported_failures = 0;
        if (!tu_cpu_supported()) GTEST_SKIP() << "this CPU lacks " << WT_SIMD_TEST_ISA_NAME;
    }
};
TYPED_TEST_SUITE_P(SimdWidth);

TYPED_TEST_P(SimdWidth, TraitsStepBroadcastAndLaneAccess) {
    using F = typename TypeParam::F;
    using I = typename TypeParam::I;
    using B = typename TypeParam::B;
    constexpr int n = TypeParam::N;
    static_assert(F::N == n && I::N == n && B::N == n, "lane count");
    EXPECT_EQ(F::fused_madd, fused_madd);
    EXPECT_EQ(F::fused_madd, vfloat<1>::fused_madd);
    const I step = I::step();
    const F pi(3.14159f);
    const I seven(7);
    for (int i = 0; i < n; ++i) {
        EXPECT_EQ(step[i], i);
        EXPECT_EQ(float_to_bits(pi[i]), float_to_bits(3.14159f));
        EXPECT_EQ(seven[i], 7);
        EXPECT_TRUE(B(true)[i]);
        EXPECT_FALSE(B(false)[i]);
    }
    // The broadcast constructors are implicit, so scalars mix with vectors.
    const F doubled = F(1.5f) * 2.0f;
    const I bumped = step + 1;
    for (int i = 0; i < n; ++i) {
        EXPECT_EQ(doubled[i], 3.0f);
        EXPECT_EQ(bumped[i], i + 1);
    }
}

TYPED_TEST_P(SimdWidth, AlignedAndUnalignedLoadStore) {
    using F = typename TypeParam::F;
    using I = typename TypeParam::I;
    constexpr int n = TypeParam::N;
    alignas(64) float fsrc[2 * n + 16];
    alignas(64) int32_t isrc[2 * n + 16];
    for (int i = 0; i < 2 * n + 16; ++i) {
        fsrc[i] = 0.25f * static_cast<float>(i) - 3.0f;
        isrc[i] = i * 1000003 - 7;
    }
    alignas(64) float fdst[n];
    alignas(64) int32_t idst[n];
    F::store(fdst, F::load(fsrc));
    I::store(idst, I::load(isrc));
    for (int i = 0; i < n; ++i) {
        EXPECT_EQ(fdst[i], fsrc[i]);
        EXPECT_EQ(idst[i], isrc[i]);
    }
    for (int offset = 0; offset < 16; ++offset) {
        float fout[n + 2];
        int32_t iout[n + 2];
        fout[0] = fout[n + 1] = -1.0f;
        iout[0] = iout[n + 1] = -1;
        const F fv = F::loadu(fsrc + offset);
        const I iv = I::loadu(isrc + offset);
        F::storeu(fout + 1, fv);
        I::storeu(iout + 1, iv);
        for (int i = 0; i < n; ++i) {
            EXPECT_EQ(fv[i], fsrc[offset + i]);
            EXPECT_EQ(iv[i], isrc[offset + i]);
            EXPECT_EQ(fout[1 + i], fsrc[offset + i]);
            EXPECT_EQ(iout[1 + i], isrc[offset + i]);
        }
        EXPECT_EQ(fout[0], -1.0f);
        EXPECT_EQ(fout[n + 1], -1.0f);
        EXPECT_EQ(iout[0], -1);
        EXPECT_EQ(iout[n + 1], -1);
    }
}

// load_partial(p, count, fill) for every count: p is placed so that element `count` would be
// on the guard page, so reading past the count crashes.
TYPED_TEST_P(SimdWidth, LoadPartialEveryCount) {
    using F = typename TypeParam::F;
    using I = typename TypeParam::I;
    constexpr int n = TypeParam::N;
    GuardedPage page;
    ASSERT_TRUE(page.ok());
    const float ffill = bits_to_float(0x7fc0beefu);  // a NaN: must arrive bit-exact
    for (int count = -1; count <= n + 2; ++count) {
        const int stored = std::clamp(count, 0, n);
        float* fp = page.last<float>(stored);
        int32_t* ip = page.last<int32_t>(stored);
        for (int i = 0; i < stored; ++i) {
            fp[i] = static_cast<float>(i + 1) * -1.25f;
            ip[i] = (i + 1) * 77;
        }
        const F fv = F::load_partial(fp, count, ffill);
        const I iv = I::load_partial(ip, count, -5);
        for (int i = 0; i < n; ++i) {
            SCOPED_TRACE("count " + std::to_string(count) + " lane " + std::to_string(i));
            if (i < stored) {
                EXPECT_EQ(float_to_bits(fv[i]), float_to_bits(fp[i]));
                EXPECT_EQ(iv[i], ip[i]);
            } else {
                EXPECT_EQ(float_to_bits(fv[i]), float_to_bits(ffill));
                EXPECT_EQ(iv[i], -5);
            }
        }
    }
}

// store_partial(p, v, count) for every count: writes exactly lanes [0, count), ends at the
// guard page, and leaves the sentinel before p alone.
TYPED_TEST_P(SimdWidth, StorePartialEveryCount) {
    using F = typename TypeParam::F;
    using I = typename TypeParam::I;
    constexpr int n = TypeParam::N;
    GuardedPage page;
    ASSERT_TRUE(page.ok());
    const F fv = to_float(I::step()) + 0.5f;
    const I iv = I::step() * 3 + 1;
    for (int count = -1; count <= n + 2; ++count) {
        const int stored = std::clamp(count, 0, n);
        float* fp = page.last<float>(n + 1);  // n + 1 slots: a sentinel, then n lanes max
        int32_t* ip = page.last<int32_t>(n + 1);
        std::fill(fp, fp + n + 1, -9.0f);
        float* fdst = page.last<float>(stored);
        F::store_partial(fdst, fv, count);
        for (int i = 0; i < n + 1; ++i) {
            const int lane = static_cast<int>(fp + i - fdst);
            const bool written = lane >= 0 && lane < stored;
            EXPECT_EQ(fp[i], written ? fv[lane] : -9.0f) << "count " << count << " slot " << i;
        }
        std::fill(ip, ip + n + 1, -9);
        int32_t* idst = page.last<int32_t>(stored);
        I::store_partial(idst, iv, count);
        for (int i = 0; i < n + 1; ++i) {
            const int lane = static_cast<int>(ip + i - idst);
            const bool written = lane >= 0 && lane < stored;
            EXPECT_EQ(ip[i], written ? iv[lane] : -9) << "count " << count << " slot " << i;
        }
    }
}

// load_masked / store_masked with every lane pattern (random ones for 16 lanes).
TYPED_TEST_P(SimdWidth, MaskedLoadStoreEveryPattern) {
    using F = typename TypeParam::F;
    using I = typename TypeParam::I;
    using B = typename TypeParam::B;
    constexpr int n = TypeParam::N;
    float fsrc[n];
    int32_t isrc[n];
    for (int i = 0; i < n; ++i) {
        fsrc[i] = static_cast<float>(i) + 0.75f;
        isrc[i] = -100 * (i + 1);
    }
    const F fv = F::loadu(fsrc);
    const I iv = I::loadu(isrc);
    for (uint32_t bits : mask_patterns(n, 11)) {
        const B m = B::from_bits(bits);
        const F fl = F::load_masked(m, fsrc);
        const I il = I::load_masked(m, isrc);
        float fdst[n];
        int32_t idst[n];
        std::fill(fdst, fdst + n, -1.0f);
        std::fill(idst, idst + n, -1);
        F::store_masked(m, fdst, fv * 2.0f);
        I::store_masked(m, idst, iv * 2);
        for (int i = 0; i < n; ++i) {
            const bool on = (bits >> i) & 1;
            ASSERT_EQ(float_to_bits(fl[i]), float_to_bits(on ? fsrc[i] : 0.0f)) << "mask " << bits << " lane " << i;
            ASSERT_EQ(il[i], on ? isrc[i] : 0) << "mask " << bits << " lane " << i;
            ASSERT_EQ(fdst[i], on ? 2.0f * fsrc[i] : -1.0f) << "mask " << bits << " lane " << i;
            ASSERT_EQ(idst[i], on ? 2 * isrc[i] : -1) << "mask " << bits << " lane " << i;
        }
    }
    // Inactive lanes must not be touched at all: lanes >= k lie on the guard page.
    GuardedPage page;
    ASSERT_TRUE(page.ok());
    for (int k = 0; k <= n; ++k) {
        float* fp = page.last<float>(k);
        int32_t* ip = page.last<int32_t>(k);
        for (int i = 0; i < k; ++i) {
            fp[i] = static_cast<float>(i);
            ip[i] = i;
        }
        for (uint32_t bits : mask_patterns(n, 12, 200)) {
            bits &= (1u << k) - 1u;
            const B m = B::from_bits(bits);
            const F fl = F::load_masked(m, fp);
            const I il = I::load_masked(m, ip);
            F::store_masked(m, fp, fl + 1.0f);
            I::store_masked(m, ip, il + 1);
            F::store_masked(m, fp, fl);
            I::store_masked(m, ip, il);
        }
    }
}

TYPED_TEST_P(SimdWidth, GatherAndMaskedGather) {
    using F = typename TypeParam::F;
    using I = typename TypeParam::I;
    using B = typename TypeParam::B;
    constexpr int n = TypeParam::N;
    // The table ends at the guard page; inactive lanes get an index on the guard page, so a
    // gather that reads them crashes.
    constexpr int table_size = 1000;
    GuardedPage fpage, ipage;
    ASSERT_TRUE(fpage.ok() && ipage.ok());
    float* ftable = fpage.last<float>(table_size);
    int32_t* itable = ipage.last<int32_t>(table_size);
    for (int i = 0; i < table_size; ++i) {
        ftable[i] = std::sqrt(static_cast<float>(i)) - 10.0f;
        itable[i] = i * i - 12345;
    }
    std::mt19937 rng(21);
    std::uniform_int_distribution<int32_t> index(0, table_size - 1);
    const std::vector<uint32_t> patterns = mask_patterns(n, 22, 500);
    for (size_t round = 0; round < patterns.size(); ++round) {
        int32_t idx[n];
        for (int i = 0; i < n; ++i) idx[i] = index(rng);
        if (round == 0)
            for (int i = 0; i < n; ++i) idx[i] = i == 0 ? 0 : table_size - 1;  // both ends
        const I vidx = I::loadu(idx);
        const F fg = F::gather(ftable, vidx);
        const I ig = I::gather(itable, vidx);
        const uint32_t bits = patterns[round];
        int32_t wild[n];
        for (int i = 0; i < n; ++i) wild[i] = (bits >> i) & 1 ? idx[i] : table_size + 16 + i;
        const B m = B::from_bits(bits);
        const F fmg = F::gather(m, ftable, I::loadu(wild));
        const I img = I::gather(m, itable, I::loadu(wild));
        for (int i = 0; i < n; ++i) {
            const bool on = (bits >> i) & 1;
            ASSERT_EQ(fg[i], ftable[idx[i]]);
            ASSERT_EQ(ig[i], itable[idx[i]]);
            ASSERT_EQ(float_to_bits(fmg[i]), float_to_bits(on ? ftable[idx[i]] : 0.0f)) << "mask " << bits;
            ASSERT_EQ(img[i], on ? itable[idx[i]] : 0) << "mask " << bits;
        }
    }
    // Negative indices are signed element offsets.
    const I back = -I::step();
    const F fneg = F::gather(ftable + (table_size - 1), back);
    for (int i = 0; i < n; ++i) EXPECT_EQ(fneg[i], ftable[table_size - 1 - i]);
}

TYPED_TEST_P(SimdWidth, FloatArithmetic) {
    using W = TypeParam;
    const FloatOperands ops = float_operands(31);
    for_each_packet<W>(ops, [](auto a, auto b, auto) {
        check_lanes("a + b", Cmp::value, [](auto x, auto y) { return x + y; }, a, b);
        check_lanes("a - b", Cmp::value, [](auto x, auto y) { return x - y; }, a, b);
        check_lanes("a * b", Cmp::value, [](auto x, auto y) { return x * y; }, a, b);
        check_lanes("a / b", Cmp::value, [](auto x, auto y) { return x / y; }, a, b);
        check_lanes("-a", Cmp::bits, [](auto x) { return -x; }, a);
        check_lanes("a += b", Cmp::value, [](auto x, auto y) { return x += y; }, a, b);
        check_lanes("a -= b", Cmp::value, [](auto x, auto y) { return x -= y; }, a, b);
        check_lanes("a *= b", Cmp::value, [](auto x, auto y) { return x *= y; }, a, b);
        check_lanes("a /= b", Cmp::value, [](auto x, auto y) { return x /= y; }, a, b);
    });
}

// Independent references for the multiply-adds: std::fma when the TU fuses, otherwise a
// product rounded to float (volatile: the compiler may not contract it) and then the add.
float ref_mul(float a, float b) {
    volatile float p = a * b;
    return p;
}
float ref_madd(float a, float b, float c) { return fused_madd ? std::fma(a, b, c) : ref_mul(a, b) + c; }
float ref_msub(float a, float b, float c) { return fused_madd ? std::fma(a, b, -c) : ref_mul(a, b) - c; }
float ref_nmadd(float a, float b, float c) { return fused_madd ? std::fma(-a, b, c) : c - ref_mul(a, b); }
float ref_nmsub(float a, float b, float c) { return fused_madd ? std::fma(-a, b, -c) : -ref_mul(a, b) - c; }

TYPED_TEST_P(SimdWidth, FusedMultiplyAdd) {
    using W = TypeParam;
    using F = typename W::F;
    constexpr int n = W::N;
    FloatOperands ops = float_operands(41);
    // Add cancellation cases c = -round(a*b): fused gives the exact rounding error of a*b,
    // unfused gives 0. This is where the two differ most, and it shows which one ran.
    std::mt19937 rng(42);
    const std::vector<float> ra = random_floats(rng, 1600), rb = random_floats(rng, 1600);
    for (size_t i = 0; i < ra.size(); ++i) {
        ops.a.push_back(ra[i]);
        ops.b.push_back(rb[i]);
        ops.c.push_back(-ref_mul(ra[i], rb[i]));
    }
    int residuals = 0;
    for_each_packet<W>(ops, [&](F a, F b, F c) {
        check_lanes("madd", Cmp::value, [](auto x, auto y, auto z) { return madd(x, y, z); }, a, b, c);
        check_lanes("msub", Cmp::value, [](auto x, auto y, auto z) { return msub(x, y, z); }, a, b, c);
        check_lanes("nmadd", Cmp::value, [](auto x, auto y, auto z) { return nmadd(x, y, z); }, a, b, c);
        check_lanes("nmsub", Cmp::value, [](auto x, auto y, auto z) { return nmsub(x, y, z); }, a, b, c);
        const F r1 = madd(a, b, c), r2 = msub(a, b, c), r3 = nmadd(a, b, c), r4 = nmsub(a, b, c);
        for (int i = 0; i < n; ++i) {
            const float x = a[i], y = b[i], z = c[i];
            ASSERT_TRUE(same_value(r1[i], ref_madd(x, y, z))) << show_operands(x, y, z) << " madd " << show(r1[i]);
            ASSERT_TRUE(same_value(r2[i], ref_msub(x, y, z))) << show_operands(x, y, z) << " msub " << show(r2[i]);
            ASSERT_TRUE(same_value(r3[i], ref_nmadd(x, y, z))) << show_operands(x, y, z) << " nmadd " << show(r3[i]);
            ASSERT_TRUE(same_value(r4[i], ref_nmsub(x, y, z))) << show_operands(x, y, z) << " nmsub " << show(r4[i]);
            if (std::isfinite(r1[i]) && r1[i] != 0.0f && z == -ref_mul(x, y)) ++residuals;
        }
    });
    EXPECT_EQ(residuals > 0, fused_madd) << "cancellation cases with a nonzero result: " << residuals;
    // The textbook case: (1 + 2^-23)^2 - (1 + 2^-22) is 2^-46 exactly, 0 after rounding a*b.
    const float a = 1.0f + std::ldexp(1.0f, -23), c = -(1.0f + std::ldexp(1.0f, -22));
    const float r = madd(F(a), F(a), F(c))[n - 1];
    EXPECT_EQ(r, fused_madd ? std::ldexp(1.0f, -46) : 0.0f);
}

TYPED_TEST_P(SimdWidth, MinMaxNaNAndSignedZero) {
    using W = TypeParam;
    using F = typename W::F;
    const FloatOperands ops = float_operands(51);
    for_each_packet<W>(ops, [](F a, F b, F) {
        check_lanes("min", Cmp::bits, [](auto x, auto y) { return min(x, y); }, a, b);
        check_lanes("max", Cmp::bits, [](auto x, auto y) { return max(x, y); }, a, b);
    });
    // The documented rule, spelled out (bits matter: which NaN, which zero).
    const float nan = bits_to_float(0x7fc01234u);
    EXPECT_EQ(min(F(nan), F(1.0f))[0], 1.0f);
    EXPECT_EQ(float_to_bits(min(F(1.0f), F(nan))[0]), 0x7fc01234u);
    EXPECT_EQ(max(F(nan), F(1.0f))[0], 1.0f);
    EXPECT_EQ(float_to_bits(max(F(1.0f), F(nan))[0]), 0x7fc01234u);
    EXPECT_EQ(float_to_bits(min(F(0.0f), F(-0.0f))[0]), 0x80000000u);
    EXPECT_EQ(float_to_bits(min(F(-0.0f), F(0.0f))[0]), 0u);
    EXPECT_EQ(float_to_bits(max(F(-0.0f), F(0.0f))[0]), 0u);
    EXPECT_EQ(float_to_bits(max(F(0.0f), F(-0.0f))[0]), 0x80000000u);
}

TYPED_TEST_P(SimdWidth, AbsSqrtRcpRsqrtFloorCeil) {
    using W = TypeParam;
    using F = typename W::F;
    const FloatOperands ops = float_operands(61);
    for_each_packet<W>(ops, [](F a, F, F) {
        check_lanes("abs", Cmp::bits, [](auto x) { return abs(x); }, a);
        check_lanes("sqrt", Cmp::value, [](auto x) { return sqrt(x); }, a);
        check_lanes("rcp", Cmp::value, [](auto x) { return rcp(x); }, a);
        check_lanes("rsqrt", Cmp::value, [](auto x) { return rsqrt(x); }, a);
        check_lanes("floor", Cmp::value, [](auto x) { return floor(x); }, a);
        check_lanes("ceil", Cmp::value, [](auto x) { return ceil(x); }, a);
    });
    EXPECT_EQ(rcp(F(0.0f))[0], kInf);
    EXPECT_EQ(rcp(F(-0.0f))[0], -kInf);
    EXPECT_EQ(float_to_bits(rcp(F(-kInf))[0]), 0x80000000u);
    EXPECT_EQ(rsqrt(F(4.0f))[0], 0.5f);
    EXPECT_EQ(float_to_bits(floor(F(-0.0f))[0]), 0x80000000u);
    EXPECT_EQ(float_to_bits(ceil(F(-0.5f))[0]), 0x80000000u);
}

// The stated bounds for rcp_fast / rsqrt_fast (vfloat.h), in ulp of the exact rcp / rsqrt.
constexpr int64_t kRcpFastUlpBound = 4;
constexpr int64_t kRsqrtFastUlpBound = 5;

TYPED_TEST_P(SimdWidth, FastReciprocalsWithinUlpBound) {
    using W = TypeParam;
    using F = typename W::F;
    using I = typename W::I;
    constexpr int n = W::N;
    int64_t worst_rcp = 0, worst_rsqrt = 0;
    // Every float in [1, 2) for rcp and [1, 4) for rsqrt (the estimate tables repeat with the
    // exponent, or with its parity for rsqrt), negated too for rcp.
    auto track = [](int64_t& worst, const F& got, const F& want) {
        const std::array<float, n> g = to_array(got), w = to_array(want);
        for (int i = 0; i < n; ++i) worst = std::max(worst, ulp_distance(g[i], w[i]));
    };
    const I mantissa_step = I::step();
    for (int32_t base = 0x3f800000; base < 0x40800000; base += n) {
        const F x = asFloat(I(base) + mantissa_step);
        track(worst_rsqrt, rsqrt_fast(x), rsqrt(x));
        if (base < 0x40000000) {
            track(worst_rcp, rcp_fast(x), rcp(x));
            track(worst_rcp, rcp_fast(-x), rcp(-x));
        }
    }
    // Random normal inputs over the whole documented range: |x| in [2^-126, 2^125) for rcp
    // (above that the SSE estimate may flush its tiny result to 0), all normals for rsqrt.
    std::mt19937 rng(71);
    std::uniform_int_distribution<int32_t> exponent(-126, 127);
    std::uniform_int_distribution<int32_t> mantissa(0, (1 << 23) - 1);
    for (int round = 0; round < 20000; ++round) {
        alignas(64) float in[n];
        for (int i = 0; i < n; ++i)
            in[i] = bits_to_float(static_cast<uint32_t>(((exponent(rng) + 127) << 23) | mantissa(rng)) |
                                  (i % 2 ? 0x80000000u : 0u));
        const F x = F::loadu(in);
        track(worst_rsqrt, rsqrt_fast(abs(x)), rsqrt(abs(x)));
        const F in_rcp_range = select(abs(x) < F(std::ldexp(1.0f, 125)), x, F(1.0f));
        track(worst_rcp, rcp_fast(in_rcp_range), rcp(in_rcp_range));
    }
    EXPECT_LE(worst_rcp, kRcpFastUlpBound);
    EXPECT_LE(worst_rsqrt, kRsqrtFastUlpBound);
    ::testing::Test::RecordProperty("worst_rcp_fast_ulp", static_cast<int>(worst_rcp));
    ::testing::Test::RecordProperty("worst_rsqrt_fast_ulp", static_cast<int>(worst_rsqrt));
    std::printf("  [w%d] worst rcp_fast: %lld ulp, worst rsqrt_fast: %lld ulp\n", n, static_cast<long long>(worst_rcp),
                static_cast<long long>(worst_rsqrt));

    // Exact where documented: zeros, infinities, NaN, negative rsqrt.
    EXPECT_EQ(float_to_bits(rcp_fast(F(0.0f))[0]), float_to_bits(kInf));
    EXPECT_EQ(float_to_bits(rcp_fast(F(-0.0f))[0]), float_to_bits(-kInf));
    EXPECT_EQ(float_to_bits(rcp_fast(F(kInf))[0]), 0u);
    EXPECT_EQ(float_to_bits(rcp_fast(F(-kInf))[0]), 0x80000000u);
    EXPECT_TRUE(std::isnan(rcp_fast(F(std::nanf("")))[0]));
    EXPECT_EQ(float_to_bits(rsqrt_fast(F(0.0f))[0]), float_to_bits(kInf));
    EXPECT_EQ(float_to_bits(rsqrt_fast(F(-0.0f))[0]), float_to_bits(-kInf));
    EXPECT_EQ(float_to_bits(rsqrt_fast(F(kInf))[0]), 0u);
    EXPECT_TRUE(std::isnan(rsqrt_fast(F(-1.0f))[0]));
    EXPECT_TRUE(std::isnan(rsqrt_fast(F(std::nanf("")))[0]));
    // Outside the normal range: within the bound, or the documented flush (+-inf for denormal
    // inputs, +-0 for |x| > 2^126).
    for (uint32_t u : {0x00000001u, 0x00400000u, 0x007fffffu, 0x80200000u, 0x7f000001u, 0x7f7fffffu, 0xff7fffffu}) {
        const float x = bits_to_float(u);
        const float q = rcp_fast(F(x))[0], want = rcp(F(x))[0];
        EXPECT_TRUE(ulp_distance(q, want) <= kRcpFastUlpBound || (std::isinf(q) && std::signbit(q) == std::signbit(x)) ||
                    (q == 0.0f && std::signbit(q) == std::signbit(x)))
            << "rcp_fast(" << show(x) << ") = " << show(q);
        if (x > 0.0f) {
            const float r = rsqrt_fast(F(x))[0], want_r = rsqrt(F(x))[0];
            EXPECT_TRUE(ulp_distance(r, want_r) <= kRsqrtFastUlpBound || r == kInf)
                << "rsqrt_fast(" << show(x) << ") = " << show(r);
        }
    }
}

TYPED_TEST_P(SimdWidth, FloatComparisons) {
    using W = TypeParam;
    using F = typename W::F;
    const FloatOperands ops = float_operands(81);
    for_each_packet<W>(ops, [](F a, F b, F) {
        check_lanes("a < b", Cmp::bits, [](auto x, auto y) { return x < y; }, a, b);
        check_lanes("a <= b", Cmp::bits, [](auto x, auto y) { return x <= y; }, a, b);
        check_lanes("a > b", Cmp::bits, [](auto x, auto y) { return x > y; }, a, b);
        check_lanes("a >= b", Cmp::bits, [](auto x, auto y) { return x >= y; }, a, b);
        check_lanes("a == b", Cmp::bits, [](auto x, auto y) { return x == y; }, a, b);
        check_lanes("a != b", Cmp::bits, [](auto x, auto y) { return x != y; }, a, b);
        check_lanes("a == a", Cmp::bits, [](auto x) { return x == x; }, a);
    });
}

// flip_sign against an oracle written with std::signbit, on the operand set's NaNs, zeros,
// infinities and subnormals: a's bits with the sign toggled exactly where b's sign bit is set.
TYPED_TEST_P(SimdWidth, FlipSign) {
    using W = TypeParam;
    using F = typename W::F;
    constexpr int n = W::N;
    const FloatOperands ops = float_operands(83);
    for_each_packet<W>(ops, [](F a, F b, F) {
        const F got = flip_sign(a, b);
        for (int i = 0; i < n; ++i) {
            const uint32_t want = float_to_bits(a[i]) ^ (std::signbit(b[i]) ? 0x80000000u : 0u);
            ASSERT_EQ(float_to_bits(got[i]), want) << "flip_sign(" << show(a[i]) << ", " << show(b[i]) << ")";
        }
    });
}

TYPED_TEST_P(SimdWidth, SelectEveryPattern) {
    using W = TypeParam;
    using F = typename W::F;
    using I = typename W::I;
    using B = typename W::B;
    constexpr int n = W::N;
    const FloatOperands ops = float_operands(91);
    std::mt19937 rng(92);
    const std::vector<int32_t> ints = random_ints(rng, 2 * 16 * 64);
    const std::vector<uint32_t> patterns = mask_patterns(n, 93);
    for (size_t k = 0; k < patterns.size(); ++k) {
        const B m = B::from_bits(patterns[k]);
        const size_t p = (k * n) % (ops.a.size() - n);
        const size_t q = (k * n) % (ints.size() / 2 - n);
        const F a = F::loadu(&ops.a[p]), b = F::loadu(&ops.b[p]);
        const I ia = I::loadu(&ints[q]), ib = I::loadu(&ints[ints.size() / 2 + q]);
        check_lanes("select float", Cmp::bits, [](auto mm, auto x, auto y) { return select(mm, x, y); }, m, a, b);
        check_lanes("select int", Cmp::bits, [](auto mm, auto x, auto y) { return select(mm, x, y); }, m, ia, ib);
        const F s = select(m, a, b);
        for (int i = 0; i < n; ++i)
            ASSERT_EQ(float_to_bits(s[i]), float_to_bits((patterns[k] >> i) & 1 ? a[i] : b[i]));
    }
}

TYPED_TEST_P(SimdWidth, MaskLogicEveryPattern) {
    using W = TypeParam;
    using B = typename W::B;
    constexpr int n = W::N;
    const uint32_t full = (1u << n) - 1u;
    const std::vector<uint32_t> pa = mask_patterns(n, 101, 300), pb = mask_patterns(n, 102, 300);
    EXPECT_EQ(movemask(B(true)), full);
    EXPECT_EQ(movemask(B(false)), 0u);
    for (uint32_t x : pa) {
        const B a = B::from_bits(x | (0xdead0000u << n));  // bits above N are ignored
        ASSERT_EQ(movemask(a), x);
        for (int i = 0; i < n; ++i) ASSERT_EQ(a[i], ((x >> i) & 1) != 0);
        ASSERT_EQ(any(a), x != 0);
        ASSERT_EQ(all(a), x == full);
        ASSERT_EQ(none(a), x == 0);
        ASSERT_EQ(popcount(a), __builtin_popcount(x));
        ASSERT_EQ(movemask(~a), ~x & full);
        check_lanes("~a", Cmp::bits, [](auto u) { return ~u; }, a);
        for (uint32_t y : pb) {
            const B b = B::from_bits(y);
            ASSERT_EQ(movemask(a & b), x & y);
            ASSERT_EQ(movemask(a | b), x | y);
            ASSERT_EQ(movemask(a ^ b), x ^ y);
            ASSERT_EQ(movemask(andnot(a, b)), x & ~y);
            ASSERT_EQ(movemask(a == b), ~(x ^ y) & full);
            ASSERT_EQ(movemask(a != b), x ^ y);
            B c = a;
            c &= b;
            ASSERT_EQ(movemask(c), x & y);
            c = a;
            c |= b;
            ASSERT_EQ(movemask(c), x | y);
            c = a;
            c ^= b;
            ASSERT_EQ(movemask(c), x ^ y);
        }
        // Lane by lane against width 1 as well, for one partner pattern per x.
        const B b = B::from_bits(pb[x % pb.size()]);
        check_lanes("a & b", Cmp::bits, [](auto u, auto v) { return u & v; }, a, b);
        check_lanes("a | b", Cmp::bits, [](auto u, auto v) { return u | v; }, a, b);
        check_lanes("a ^ b", Cmp::bits, [](auto u, auto v) { return u ^ v; }, a, b);
        check_lanes("andnot", Cmp::bits, [](auto u, auto v) { return andnot(u, v); }, a, b);
        check_lanes("a == b", Cmp::bits, [](auto u, auto v) { return u == v; }, a, b);
        check_lanes("a != b", Cmp::bits, [](auto u, auto v) { return u != v; }, a, b);
    }
}

// The halving fold of vfloat.h, on width 1.
template <int N, typename Op>
float halving_fold(std::array<float, N> x, Op op) {
    for (int h = N / 2; h >= 1; h /= 2)
        for (int i = 0; i < h; ++i) x[i] = op(vfloat<1>(x[i]), vfloat<1>(x[i + h])).v;
    return x[0];
}

TYPED_TEST_P(SimdWidth, HorizontalReductions) {
    using W = TypeParam;
    using F = typename W::F;
    constexpr int n = W::N;
    const FloatOperands ops = float_operands(111);
    std::mt19937 rng(112);
    std::uniform_real_distribution<float> unit(-1000.0f, 1000.0f);
    for_each_packet<W>(ops, [&](F a, F, F) {
        const std::array<float, n> x = to_array(a);
        const float got_min = reduce_min(a), got_max = reduce_max(a), got_add = reduce_add(a);
        const float want_min = halving_fold<n>(x, [](auto u, auto v) { return min(u, v); });
        const float want_max = halving_fold<n>(x, [](auto u, auto v) { return max(u, v); });
        const float want_add = halving_fold<n>(x, [](auto u, auto v) { return u + v; });
        ASSERT_EQ(float_to_bits(got_min), float_to_bits(want_min)) << show(got_min) << " vs " << show(want_min);
        ASSERT_EQ(float_to_bits(got_max), float_to_bits(want_max)) << show(got_max) << " vs " << show(want_max);
        ASSERT_TRUE(same_value(got_add, want_add)) << show(got_add) << " vs " << show(want_add);
    });
    // Without NaN the fold is the ordinary minimum / maximum, and the sum is close to exact.
    for (int round = 0; round < 2000; ++round) {
        std::array<float, n> x;
        for (float& v : x) v = unit(rng);
        const F a = F::loadu(x.data());
        EXPECT_EQ(reduce_min(a), *std::min_element(x.begin(), x.end()));
        EXPECT_EQ(reduce_max(a), *std::max_element(x.begin(), x.end()));
        double exact = 0.0;
        for (float v : x) exact += v;
        EXPECT_NEAR(reduce_add(a), exact, 1e-3 * n);
    }
}

TYPED_TEST_P(SimdWidth, SelectMinIndex) {
    using W = TypeParam;
    using F = typename W::F;
    using B = typename W::B;
    constexpr int n = W::N;
    // Independent oracle: a plain loop. Strict < keeps the lowest index on ties.
    auto oracle = [](uint32_t active, const std::array<float, n>& v) {
        int best = -1;
        for (int i = 0; i < n; ++i)
            if (((active >> i) & 1) && !std::isnan(v[i]) && (best < 0 || v[i] < v[best])) best = i;
        return best;
    };
    std::mt19937 rng(121);
    const std::vector<float> pool = {1.0f, 2.0f, -3.0f, 0.0f, -0.0f, kInf, -kInf, std::nanf(""), 1e-40f, 7.5f};
    std::uniform_int_distribution<size_t> pick(0, pool.size() - 1);
    std::uniform_real_distribution<float> any_value(-1e6f, 1e6f);
    for (uint32_t bits : mask_patterns(n, 122, 3000)) {
        for (int variant = 0; variant < 3; ++variant) {
            std::array<float, n> v;
            for (int i = 0; i < n; ++i) v[i] = variant == 0 ? any_value(rng) : pool[pick(rng)];
            if (variant == 2) std::fill(v.begin(), v.end(), kInf);  // all-inf: still a hit
            const int got = select_min_index(B::from_bits(bits), F::loadu(v.data()));
            const int want = oracle(bits, v);
            ASSERT_EQ(got, want) << "mask " << bits << " variant " << variant;
        }
    }
    EXPECT_EQ(select_min_index(B(true), F(std::nanf(""))), -1);
    EXPECT_EQ(select_min_index(B(false), F(1.0f)), -1);
    EXPECT_EQ(select_min_index(B(true), F(5.0f)), 0);
}

TYPED_TEST_P(SimdWidth, IntArithmeticAndBitwise) {
    using W = TypeParam;
    using I = typename W::I;
    constexpr int n = W::N;
    std::mt19937 rng(131);
    const std::vector<int32_t> a = random_ints(rng, 4096), b = random_ints(rng, 4096);
    for (size_t p = 0; p + n <= a.size(); p += n) {
        // b shifted by one lane-ish offset so the edge values meet each other, not themselves.
        const I x = I::loadu(&a[p]), y = I::loadu(&b[(p + 3) % (b.size() - n)]);
        check_lanes("a + b", Cmp::bits, [](auto u, auto v) { return u + v; }, x, y);
        check_lanes("a - b", Cmp::bits, [](auto u, auto v) { return u - v; }, x, y);
        check_lanes("a * b", Cmp::bits, [](auto u, auto v) { return u * v; }, x, y);
        check_lanes("-a", Cmp::bits, [](auto u) { return -u; }, x);
        check_lanes("a & b", Cmp::bits, [](auto u, auto v) { return u & v; }, x, y);
        check_lanes("a | b", Cmp::bits, [](auto u, auto v) { return u | v; }, x, y);
        check_lanes("a ^ b", Cmp::bits, [](auto u, auto v) { return u ^ v; }, x, y);
        check_lanes("~a", Cmp::bits, [](auto u) { return ~u; }, x);
        check_lanes("a += b", Cmp::bits, [](auto u, auto v) { return u += v; }, x, y);
        check_lanes("a -= b", Cmp::bits, [](auto u, auto v) { return u -= v; }, x, y);
        check_lanes("a *= b", Cmp::bits, [](auto u, auto v) { return u *= v; }, x, y);
        check_lanes("a &= b", Cmp::bits, [](auto u, auto v) { return u &= v; }, x, y);
        check_lanes("a |= b", Cmp::bits, [](auto u, auto v) { return u |= v; }, x, y);
        check_lanes("a ^= b", Cmp::bits, [](auto u, auto v) { return u ^= v; }, x, y);
        check_lanes("min", Cmp::bits, [](auto u, auto v) { return min(u, v); }, x, y);
        check_lanes("max", Cmp::bits, [](auto u, auto v) { return max(u, v); }, x, y);
        check_lanes("a < b", Cmp::bits, [](auto u, auto v) { return u < v; }, x, y);
        check_lanes("a <= b", Cmp::bits, [](auto u, auto v) { return u <= v; }, x, y);
        check_lanes("a > b", Cmp::bits, [](auto u, auto v) { return u > v; }, x, y);
        check_lanes("a >= b", Cmp::bits, [](auto u, auto v) { return u >= v; }, x, y);
        check_lanes("a == b", Cmp::bits, [](auto u, auto v) { return u == v; }, x, y);
        check_lanes("a != b", Cmp::bits, [](auto u, auto v) { return u != v; }, x, y);
        check_lanes("a == a", Cmp::bits, [](auto u) { return u == u; }, x);
        check_lanes("a <= a", Cmp::bits, [](auto u) { return u <= u; }, x);
    }
}

TYPED_TEST_P(SimdWidth, IntShiftsEveryCount) {
    using W = TypeParam;
    using I = typename W::I;
    constexpr int n = W::N;
    std::mt19937 rng(141);
    const std::vector<int32_t> a = random_ints(rng, 512);
    for (size_t p = 0; p + n <= a.size(); p += n) {
        const I x = I::loadu(&a[p]);
        for (int count : {0, 1, 2, 7, 15, 16, 17, 30, 31, 32, 33, 40, 100, -1, INT32_MIN}) {
            check_lanes("a << n", Cmp::bits, [](auto u, int c) { return u << c; }, x, count);
            check_lanes("a >> n", Cmp::bits, [](auto u, int c) { return u >> c; }, x, count);
            check_lanes("srl(a, n)", Cmp::bits, [](auto u, int c) { return srl(u, c); }, x, count);
        }
    }
}

TYPED_TEST_P(SimdWidth, ConversionsAndBitCasts) {
    using W = TypeParam;
    using F = typename W::F;
    using I = typename W::I;
    constexpr int n = W::N;
    const FloatOperands ops = float_operands(151);
    for_each_packet<W>(ops, [](F a, F, F) {
        check_lanes("to_int", Cmp::bits, [](auto x) { return to_int(x); }, a);
        check_lanes("asInt", Cmp::bits, [](auto x) { return asInt(x); }, a);
        check_lanes("asFloat(asInt)", Cmp::bits, [](auto x) { return asFloat(asInt(x)); }, a);
    });
    std::mt19937 rng(152);
    const std::vector<int32_t> ints = random_ints(rng, 2048);
    for (size_t p = 0; p + n <= ints.size(); p += n) {
        const I x = I::loadu(&ints[p]);
        check_lanes("to_float", Cmp::bits, [](auto u) { return to_float(u); }, x);
        check_lanes("asFloat", Cmp::bits, [](auto u) { return asFloat(u); }, x);
    }
    EXPECT_EQ(to_int(F(-2147483648.0f))[0], INT32_MIN);
    EXPECT_EQ(to_int(F(2147483520.0f))[0], 2147483520);
    EXPECT_EQ(to_int(F(2147483648.0f))[0], INT32_MIN);
    EXPECT_EQ(to_int(F(std::nanf("")))[0], INT32_MIN);
    EXPECT_EQ(to_int(F(-1.75f))[0], -1);
    EXPECT_EQ(to_float(I(16777217))[0], 16777216.0f);  // round to nearest even
    EXPECT_EQ(asInt(F(1.0f))[0], 0x3f800000);
}

REGISTER_TYPED_TEST_SUITE_P(SimdWidth, TraitsStepBroadcastAndLaneAccess, AlignedAndUnalignedLoadStore,
                            LoadPartialEveryCount, StorePartialEveryCount, MaskedLoadStoreEveryPattern,
                            GatherAndMaskedGather, FloatArithmetic, FusedMultiplyAdd, MinMaxNaNAndSignedZero,
                            AbsSqrtRcpRsqrtFloorCeil, FastReciprocalsWithinUlpBound, FloatComparisons, FlipSign,
                            SelectEveryPattern, MaskLogicEveryPattern, HorizontalReductions, SelectMinIndex,
                            IntArithmeticAndBitwise, IntShiftsEveryCount, ConversionsAndBitCasts);

// ---------------------------------------------------------------------------------------------
// Suite 2: width 1 (the oracle) against hand-written expectations, as compiled in this TU.

template <typename W>
class ScalarReference : public ::testing::Test {
protected:
    void SetUp() override {  // width 1 is compiled with the TU's flags too (std::fma -> vfmadd)
        if (!tu_cpu_supported()) GTEST_SKIP() << "this CPU lacks " << WT_SIMD_TEST_ISA_NAME;
    }
};
TYPED_TEST_SUITE_P(ScalarReference);

TYPED_TEST_P(ScalarReference, FloatSemantics) {
    using F = typename TypeParam::F;
    static_assert(F::N == 1, "width 1 only");
    const float nan = bits_to_float(0x7fc05678u);
    // min/max: second operand on NaN or equality, unlike std::min / std::fmin.
    EXPECT_EQ(min(F(nan), F(2.0f)).v, 2.0f);
    EXPECT_EQ(float_to_bits(min(F(2.0f), F(nan)).v), 0x7fc05678u);
    EXPECT_EQ(float_to_bits(max(F(2.0f), F(nan)).v), 0x7fc05678u);
    EXPECT_EQ(float_to_bits(min(F(0.0f), F(-0.0f)).v), 0x80000000u);
    EXPECT_EQ(float_to_bits(max(F(-0.0f), F(0.0f)).v), 0u);
    EXPECT_EQ(min(F(1.0f), F(2.0f)).v, 1.0f);
    EXPECT_EQ(max(F(1.0f), F(2.0f)).v, 2.0f);
    // Sign-bit operations leave NaN payloads alone.
    EXPECT_EQ(float_to_bits((-F(nan)).v), 0xffc05678u);
    EXPECT_EQ(float_to_bits(abs(F(bits_to_float(0xffc05678u))).v), 0x7fc05678u);
    EXPECT_EQ(float_to_bits((-F(0.0f)).v), 0x80000000u);
    // Multiply-add: fused exactly when the TU has FMA.
    const float a = 1.0f + std::ldexp(1.0f, -23), c = -(1.0f + std::ldexp(1.0f, -22));
    EXPECT_EQ(madd(F(a), F(a), F(c)).v, fused_madd ? std::ldexp(1.0f, -46) : 0.0f);
    EXPECT_EQ(msub(F(a), F(a), F(-c)).v, fused_madd ? std::ldexp(1.0f, -46) : 0.0f);
    EXPECT_EQ(nmadd(F(a), F(a), F(-c)).v, fused_madd ? -std::ldexp(1.0f, -46) : 0.0f);
    EXPECT_EQ(nmsub(F(a), F(a), F(c)).v, fused_madd ? -std::ldexp(1.0f, -46) : 0.0f);
    EXPECT_EQ(madd(F(2.0f), F(3.0f), F(4.0f)).v, 10.0f);
    EXPECT_EQ(nmadd(F(2.0f), F(3.0f), F(4.0f)).v, -2.0f);
    // Reciprocals are exact; the fast ones have no estimate at width 1.
    EXPECT_EQ(rcp(F(3.0f)).v, 1.0f / 3.0f);
    EXPECT_EQ(rcp(F(-0.0f)).v, -kInf);
    EXPECT_EQ(rsqrt(F(16.0f)).v, 0.25f);
    EXPECT_EQ(rcp_fast(F(3.0f)).v, 1.0f / 3.0f);
    EXPECT_EQ(rsqrt_fast(F(2.0f)).v, 1.0f / std::sqrt(2.0f));
    // Compares and select.
    EXPECT_FALSE((F(nan) == F(nan)).v);
    EXPECT_TRUE((F(nan) != F(nan)).v);
    EXPECT_FALSE((F(nan) < F(1.0f)).v);
    EXPECT_TRUE((F(-0.0f) == F(0.0f)).v);
    EXPECT_EQ(select(vbool<1>(true), F(1.0f), F(2.0f)).v, 1.0f);
    EXPECT_EQ(select(vbool<1>(false), F(1.0f), F(2.0f)).v, 2.0f);
    // Conversions: x86 "integer indefinite" outside the range.
    EXPECT_EQ(to_int(F(2147483648.0f)).v, INT32_MIN);
    EXPECT_EQ(to_int(F(-2147483904.0f)).v, INT32_MIN);
    EXPECT_EQ(to_int(F(-2147483648.0f)).v, INT32_MIN);
    EXPECT_EQ(to_int(F(kInf)).v, INT32_MIN);
    EXPECT_EQ(to_int(F(nan)).v, INT32_MIN);
    EXPECT_EQ(to_int(F(-2.9f)).v, -2);
    EXPECT_EQ(to_int(F(2147483520.0f)).v, 2147483520);
    // Reductions and select_min_index of a single lane.
    EXPECT_EQ(reduce_add(F(5.0f)), 5.0f);
    EXPECT_EQ(select_min_index(vbool<1>(true), F(5.0f)), 0);
    EXPECT_EQ(select_min_index(vbool<1>(false), F(5.0f)), -1);
    EXPECT_EQ(select_min_index(vbool<1>(true), F(nan)), -1);
}

TYPED_TEST_P(ScalarReference, IntSemantics) {
    using I = typename TypeParam::I;
    EXPECT_EQ((I(INT32_MAX) + I(1)).v, INT32_MIN);  // wraps, no UB
    EXPECT_EQ((I(INT32_MIN) - I(1)).v, INT32_MAX);
    EXPECT_EQ((I(65536) * I(65536)).v, 0);
    EXPECT_EQ((I(-3) * I(7)).v, -21);
    EXPECT_EQ((-I(INT32_MIN)).v, INT32_MIN);
    EXPECT_EQ((I(1) << 31).v, INT32_MIN);
    EXPECT_EQ((I(1) << 32).v, 0);
    EXPECT_EQ((I(-1) << 1).v, -2);
    EXPECT_EQ((I(-8) >> 1).v, -4);  // arithmetic
    EXPECT_EQ((I(-8) >> 40).v, -1);
    EXPECT_EQ((I(8) >> 40).v, 0);
    EXPECT_EQ(srl(I(-8), 28).v, 15);  // logical
    EXPECT_EQ(srl(I(-8), 32).v, 0);
    EXPECT_EQ((I(5) << -1).v, 0);  // negative counts are huge unsigned counts
    EXPECT_EQ((I(-5) >> -1).v, -1);
    EXPECT_EQ(to_float(I(16777217)).v, 16777216.0f);
    EXPECT_EQ(min(I(-3), I(2)).v, -3);
    EXPECT_EQ(max(I(-3), I(2)).v, 2);
    EXPECT_TRUE((I(-1) < I(0)).v);
}

TYPED_TEST_P(ScalarReference, MemoryAndMasks) {
    using F = typename TypeParam::F;
    using I = typename TypeParam::I;
    using B = typename TypeParam::B;
    float f = 1.5f;
    int32_t i = 9;
    EXPECT_EQ(F::load_partial(&f, 1, 7.0f).v, 1.5f);
    EXPECT_EQ(F::load_partial(nullptr, 0, 7.0f).v, 7.0f);  // count 0 reads nothing
    EXPECT_EQ(I::load_partial(nullptr, -3, 4).v, 4);
    F::store_partial(nullptr, 2.0f, 0);  // writes nothing
    F::store_masked(B(false), nullptr, 2.0f);
    EXPECT_EQ(F::load_masked(B(false), nullptr).v, 0.0f);
    EXPECT_EQ(I::gather(B(false), nullptr, 123).v, 0);
    EXPECT_EQ(I::gather(&i, 0).v, 9);
    EXPECT_EQ(movemask(B(true)), 1u);
    EXPECT_EQ(popcount(B(true)), 1);
    EXPECT_EQ(B::from_bits(2u).v, false);
    EXPECT_EQ(andnot(B(true), B(false)).v, true);
    EXPECT_EQ(andnot(B(false), B(true)).v, false);
    EXPECT_EQ(I::step().v, 0);
}

REGISTER_TYPED_TEST_SUITE_P(ScalarReference, FloatSemantics, IntSemantics, MemoryAndMasks);

}  // namespace
