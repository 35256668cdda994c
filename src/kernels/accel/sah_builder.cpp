#include "kernels/accel/sah_builder.h"

#include <algorithm>
#include <atomic>
#include <limits>
#include <stdexcept>
#include <string>

#include "core/system/thread_pool.h"

namespace wt {
namespace {

constexpr int kMaxBins = 32;
// Past this depth every split is the object median, which halves the count: the tree stays
// shallow enough for the traversal's fixed stack whatever the input.
constexpr uint32_t kMaxSahDepth = 48;
// Ranges at least this large are binned in parallel chunks of kChunk references; the chunking
// does not depend on the thread count, and merging bins is exact in any order.
constexpr uint32_t kParallelBinning = 1u << 17;
constexpr uint32_t kChunk = 1u << 15;
// Ranges at most this large are not split further breadth first: one thread builds them whole.
constexpr uint32_t kSubtreeTask = 4096;

// A run of references and what the split search needs to know about it, computed by whoever
// produced the run (the parent's partition, or the first pass for the root).
struct Range {
    uint32_t first = 0, count = 0;
    Box box;
    Box centroids;       // of the doubled centroids, as PrimRef::centroid_times_two
    uint32_t kinds = 0;  // bit k set if some primitive of kind k is in the range

    void add(const PrimRef& r) {
        box.extend(r.box());
        centroids.extend(r.centroid_times_two());
        kinds |= 1u << r.kind;
    }
    void merge(const Range& o) {
        box.extend(o.box), centroids.extend(o.centroids), kinds |= o.kinds, count += o.count;
    }
    bool one_kind() const { return (kinds & (kinds - 1)) == 0; }
};

// Maps a doubled centroid to its bin on each axis. The binning records each reference's bins
// in it and the partition reads them back: computed again there, the float chain ahead of
// each side test made the partition a third of the build.
struct Binning {
    __m128 origin, scale;
    int bins;
    bool usable[3];

    Binning(const Box& centroids, int bin_count) : bins(bin_count) {
        origin = centroids.lo;
        alignas(16) float s[4] = {0, 0, 0, 0};
        for (int a = 0; a < 3; ++a) {
            const float extent = centroids.hi_at(a) - centroids.lo_at(a);
            usable[a] = extent > 0.0f;
            s[a] = usable[a] ? float(bins) / extent : 0.0f;
        }
        scale = _mm_load_ps(s);
    }
    // The bins on x, y and z in lanes 0-2.
    __m128i bins_of(const PrimRef& r) const {
        const __m128 f = _mm_mul_ps(_mm_sub_ps(r.centroid_times_two(), origin), scale);
        return _mm_cvttps_epi32(_mm_min_ps(_mm_max_ps(f, _mm_setzero_ps()), _mm_set1_ps(float(bins - 1))));
    }
};

// Fewer bins for small ranges: there the sweep over the bins, not the binning of the
// references, is the work, and most nodes of a tree are small.
inline int bins_for(uint32_t count) { return int(std::min<uint32_t>(kMaxBins, std::max<uint32_t>(4, count / 4))); }

// Per axis and bin, the box and count of the references binned there. Only the first
// `bins` of each axis are initialised and used (raw registers, not Box, whose constructor
// would initialise all of them: most nodes are small and use a few).
struct Bins {
    __m128 lo[3][kMaxBins], hi[3][kMaxBins];
    uint32_t count[3][kMaxBins];
    int bins;

    explicit Bins(int bin_count) : bins(bin_count) {
        const Box empty;
        for (int a = 0; a < 3; ++a)
            for (int k = 0; k < bins; ++k) lo[a][k] = empty.lo, hi[a][k] = empty.hi, count[a][k] = 0;
    }
    Box box(int a, int k) const { return Box::of(lo[a][k], hi[a][k]); }
    // Also records each reference's bins in it, for the partition.
    void add(PrimRefs& refs, uint32_t first, uint32_t end, const Binning& binning) {
        // Copies in locals, so they stay in registers: the byte stores of the bins below may
        // alias anything, and members would be read again from memory for every reference.
        const Binning map = binning;
        PrimRef* r = refs.data();
        for (uint32_t i = first; i < end; ++i) {
            const __m128i b = map.bins_of(r[i]);
            const int bin[3] = {_mm_cvtsi128_si32(b), _mm_cvtsi128_si32(_mm_shuffle_epi32(b, 1)),
                                _mm_cvtsi128_si32(_mm_shuffle_epi32(b, 2))};
            const __m128 plo = r[i].lo_xyz(), phi = r[i].hi_xyz();
            for (int a = 0; a < 3; ++a) {
                lo[a][bin[a]] = _mm_min_ps(lo[a][bin[a]], plo);
                hi[a][bin[a]] = _mm_max_ps(hi[a][bin[a]], phi);
                ++count[a][bin[a]];
                r[i].bin[a] = uint8_t(bin[a]);
            }
        }
    }
    void merge(const Bins& o) {
        for (int a = 0; a < 3; ++a)
            for (int k = 0; k < bins; ++k) {
                lo[a][k] = _mm_min_ps(lo[a][k], o.lo[a][k]);
                hi[a][k] = _mm_max_ps(hi[a][k], o.hi[a][k]);
                count[a][k] += o.count[a][k];
            }
    }
};

struct Split {
    int axis = -1;
    int bin = 0;  // references in bins [0, bin) go left
    float cost = std::numeric_limits<float>::infinity();
};

class Builder {
public:
    Builder(PrimRefs& refs, const SahSettings& settings, ThreadPool& pool)
        : refs_(refs),
          settings_(settings),
          leaf_block_shift_(settings.leaf_block ? uint32_t(__builtin_ctz(settings.leaf_block)) : 0),
          pool_(pool),
          nodes_(new BinaryNode[std::max<std::size_t>(1, 2 * refs.size())]) {
        if (settings.leaf_block == 0 || (settings.leaf_block & (settings.leaf_block - 1)) != 0)
            throw std::invalid_argument("SAH build: leaf block must be a power of two, got " + std::to_string(settings.leaf_block));
    }

    // The root on this thread (its binning in parallel chunks), then breadth first, the nodes of
    // each level split in parallel, until there are enough subtrees to keep every thread busy
    // whatever their sizes; those are then built whole, largest first. (Depth first on one
    // thread, the top levels took 40 % of a two-thread build of a million triangles.)
    BinaryTree build() {
        BinaryTree tree;
        tree.root = allocate();
        std::vector<Task> frontier = split_task({tree.root, whole_range(), 1}, true);
        const std::size_t enough = 8 * std::size_t(pool_.thread_count());
        while (frontier.size() < enough) {
            std::vector<std::vector<Task>> next(frontier.size());
            pool_.parallel_for(frontier.size(), [&](std::size_t i, int) {
                next[i] = frontier[i].range.count > kSubtreeTask ? split_task(frontier[i], false) : std::vector<Task>{frontier[i]};
            });
            std::vector<Task> flat;
            for (const auto& n : next) flat.insert(flat.end(), n.begin(), n.end());
            if (flat.size() == frontier.size()) break;  // nothing left worth splitting here
            frontier = std::move(flat);
        }
        std::sort(frontier.begin(), frontier.end(), [](const Task& a, const Task& b) { return a.range.count > b.range.count; });
        pool_.parallel_for(frontier.size(), [&](std::size_t i, int) {
            build_subtree(frontier[i].node, frontier[i].range, frontier[i].depth);
        });
        tree.max_depth = max_depth_.load();
        tree.nodes = std::move(nodes_);
        return tree;
    }

private:
    struct Task {
        uint32_t node;
        Range range;
        uint32_t depth;
    };

    uint32_t allocate() { return next_node_.fetch_add(1, std::memory_order_relaxed); }

    Range whole_range() {
        const uint32_t n = uint32_t(refs_.size());
        const uint32_t chunks = (n + kChunk - 1) / kChunk;
        std::vector<Range> parts(chunks);
        pool_.parallel_for(chunks, [&](std::size_t c, int) {
            const uint32_t end = std::min(n, uint32_t(c + 1) * kChunk);
            for (uint32_t i = uint32_t(c) * kChunk; i < end; ++i) parts[c].add(refs_[i]);
        });
        Range all;
        for (const Range& p : parts) all.merge(p);
        all.first = 0;
        all.count = n;
        return all;
    }

    // Splits the task's node once: its two children as tasks, or none if it became a leaf.
    std::vector<Task> split_task(const Task& t, bool on_pool) {
        Range left, right;
        if (!split_or_leaf(t.node, t.range, t.depth, on_pool, left, right)) return {};
        return {{nodes_[t.node].left, left, t.depth + 1}, {nodes_[t.node].right, right, t.depth + 1}};
    }

    void build_subtree(uint32_t node, const Range& range, uint32_t depth) {
        Range left, right;
        if (!split_or_leaf(node, range, depth, false, left, right)) return;
        build_subtree(nodes_[node].left, left, depth + 1);
        build_subtree(nodes_[node].right, right, depth + 1);
    }

    // Makes `node` a leaf (returns false), or splits the range into `left` and `right` and
    // allocates the node's two children. `on_pool`: this thread may use the pool (it is not
    // one of the pool's own jobs).
    bool split_or_leaf(uint32_t node, const Range& range, uint32_t depth, bool on_pool, Range& left, Range& right) {
        BinaryNode& n = nodes_[node];
        n.lo = range.box.lo, n.hi = range.box.hi;
        const uint32_t count = range.count;
        const bool may_be_leaf = count <= settings_.max_leaf_size && range.one_kind();
        if (count == 1 || (may_be_leaf && count == 2)) return make_leaf(n, range, depth);

        Split best;
        if (depth <= kMaxSahDepth) best = find_sah_split(range, on_pool);
        const float leaf_cost = settings_.primitive_cost * blocks(count);
        if (best.axis >= 0 && (!may_be_leaf || best.cost < leaf_cost)) {
            partition_at(range, best, left, right);
        } else if (may_be_leaf) {
            return make_leaf(n, range, depth);
        } else if (!range.one_kind()) {
            split_by_kind(range, left, right);  // leaves hold one kind
        } else {
            median_split(range, left, right);
        }
        n.count = 0;
        n.left = allocate();
        n.right = allocate();
        return true;
    }

    // Block tests a leaf of `count` primitives costs.
    // A shift, not an integer division by a value known only at run time: the sweep asks this
    // twice per bin.
    float blocks(uint32_t count) const { return float((count + settings_.leaf_block - 1) >> leaf_block_shift_); }

    bool make_leaf(BinaryNode& n, const Range& range, uint32_t depth) {
        n.first = range.first;
        n.count = range.count;
        n.leaf_kind = uint32_t(__builtin_ctz(range.kinds));  // one kind
        uint32_t seen = max_depth_.load(std::memory_order_relaxed);
        while (depth > seen && !max_depth_.compare_exchange_weak(seen, depth)) {
        }
        return false;
    }

    Split find_sah_split(const Range& range, bool on_pool) {
        const int bin_count = bins_for(range.count);
        const Binning binning(range.centroids, bin_count);
        if (!binning.usable[0] && !binning.usable[1] && !binning.usable[2]) return {};
        Bins bins(bin_count);
        const uint32_t end = range.first + range.count;
        if (on_pool && range.count >= kParallelBinning) {
            const uint32_t chunks = (range.count + kChunk - 1) / kChunk;
            std::vector<Bins> parts(chunks, Bins(bin_count));
            pool_.parallel_for(chunks, [&](std::size_t c, int) {
                const uint32_t begin = range.first + uint32_t(c) * kChunk;
                parts[c].add(refs_, begin, std::min(end, begin + kChunk), binning);
            });
            for (const Bins& p : parts) bins.merge(p);
        } else {
            bins.add(refs_, range.first, end, binning);
        }
        // Expected cost of a ray that enters this box: visiting the two children, plus testing
        // what each holds, weighted by the chance that a ray entering this box enters theirs.
        Split best;
        const float inv_area = 1.0f / std::max(range.box.half_area(), std::numeric_limits<float>::min());
        for (int a = 0; a < 3; ++a) {
            if (!binning.usable[a]) continue;
            float right_area[kMaxBins];
            uint32_t right_count[kMaxBins];
            Box acc;
            uint32_t n = 0;
            for (int b = bin_count - 1; b > 0; --b) {
                acc.extend(bins.box(a, b));
                n += bins.count[a][b];
                right_area[b] = acc.half_area();
                right_count[b] = n;
            }
            acc = Box();
            n = 0;
            for (int b = 1; b < bin_count; ++b) {
                acc.extend(bins.box(a, b - 1));
                n += bins.count[a][b - 1];
                if (n == 0 || right_count[b] == 0) continue;
                const float cost = settings_.node_cost + settings_.primitive_cost * inv_area *
                                                             (acc.half_area() * blocks(n) + right_area[b] * blocks(right_count[b]));
                if (cost < best.cost) best = {a, b, cost};
            }
        }
        return best;
    }

    // In place, both ends inwards, accumulating each side's bounds on the way so the children
    // need no pass of their own.
    void partition_at(const Range& range, const Split& split, Range& left, Range& right) {
        const int axis = split.axis, bin = split.bin;
        partition(range, [axis, bin](const PrimRef& r) { return r.bin[axis] < bin; }, left, right);
    }

    template <typename GoesLeft>
    void partition(const Range& range, GoesLeft&& goes_left, Range& left, Range& right) {
        // Locals, not the output references: those could alias the references' memory as far
        // as the compiler knows, and every add would go through memory.
        Range l, r;
        PrimRef* refs = refs_.data();
        int64_t i = range.first, j = int64_t(range.first) + range.count - 1;
        for (;;) {
            while (i <= j && goes_left(refs[i])) l.add(refs[i++]);
            while (i <= j && !goes_left(refs[j])) r.add(refs[j--]);
            if (i > j) break;
            std::swap(refs[i], refs[j]);
        }
        l.first = range.first;
        l.count = uint32_t(i - range.first);
        r.first = uint32_t(i);
        r.count = range.count - l.count;
        left = l, right = r;
    }

    void split_by_kind(const Range& range, Range& left, Range& right) {
        const uint32_t kind = uint32_t(__builtin_ctz(range.kinds));
        partition(range, [kind](const PrimRef& r) { return r.kind == kind; }, left, right);
    }

    // Half by centroid along the widest centroid axis; equal centroids in order of scene id,
    // so the result does not depend on how the range happened to be arranged.
    void median_split(const Range& range, Range& left, Range& right) {
        int axis = 0;
        for (int a = 1; a < 3; ++a)
            if (range.centroids.hi_at(a) - range.centroids.lo_at(a) > range.centroids.hi_at(axis) - range.centroids.lo_at(axis))
                axis = a;
        const auto begin = refs_.begin() + range.first;
        const auto mid = begin + range.count / 2;
        std::nth_element(begin, mid, begin + range.count, [axis](const PrimRef& a, const PrimRef& b) {
            const float ca = a.lo[axis] + a.hi[axis], cb = b.lo[axis] + b.hi[axis];
            return ca < cb || (ca == cb && a.id < b.id);
        });
        const uint32_t split = range.first + range.count / 2;
        left = Range(), right = Range();
        for (uint32_t i = range.first; i < split; ++i) left.add(refs_[i]);
        for (uint32_t i = split; i < range.first + range.count; ++i) right.add(refs_[i]);
        left.first = range.first, left.count = split - range.first;
        right.first = split, right.count = range.first + range.count - split;
    }

    PrimRefs& refs_;
    const SahSettings settings_;
    const uint32_t leaf_block_shift_;  // log2 of settings_.leaf_block
    ThreadPool& pool_;
    std::unique_ptr<BinaryNode[]> nodes_;
    std::atomic<uint32_t> next_node_{0};
    std::atomic<uint32_t> max_depth_{0};
};

}  // namespace

BinaryTree build_binary_sah(PrimRefs& refs, const SahSettings& settings, ThreadPool& pool) {
    return Builder(refs, settings, pool).build();
}

}  // namespace wt
