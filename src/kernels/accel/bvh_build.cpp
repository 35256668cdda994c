#include "kernels/accel/bvh.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <thread>

#include "core/thread_pool.h"
#include "kernels/accel/bvh_boxes.h"

namespace wt {
namespace {

// ---- The binary SAH tree ---------------------------------------------------------------------

// A primitive as the builder sees it: its box, its kind and its scene id. 32 bytes, moved by
// the partitions.
struct PrimRef {
    Box box;
    uint32_t id;
    BvhLeafKind kind;
    float centroid(int axis) const { return 0.5f * (box.lo[axis] + box.hi[axis]); }
};

// Node indices are handed out by an atomic counter, so with several builder threads a node's
// index depends on the schedule; the tree's shape does not, and the wide nodes are laid out by
// a walk from the root (collapse below), so the output is the same for any thread count.
struct BinaryNode {
    Box box;
    uint32_t first = 0, count = 0;  // a leaf: refs [first, first + count)
    uint32_t left = 0, right = 0;   // an inner node (count == 0)
    bool is_leaf() const { return count > 0; }
};

// Surface-area heuristic constants, in units of one primitive test. A node visit tests a ray
// against all W boxes at once; a leaf test of up to 8 primitives is one SIMD test on AVX2 and
// AVX-512, so its cost grows slowly with its size.
struct SahCosts {
    float node = 1.0f;       // one box test of a binary node
    float primitive = 1.0f;  // one primitive test
};

constexpr int kBins = 32;
// Past this depth the split is the object median: the tree stays shallow enough for the
// traversal's fixed stack whatever the input (the median halves the count every level).
constexpr uint32_t kMaxSahDepth = 48;

struct Bin {
    Box box;
    uint32_t count = 0;
};

struct Split {
    int axis = -1;
    int bin = 0;  // refs in bins [0, bin) go left
    float cost = std::numeric_limits<float>::infinity();
};

class BinaryBuilder {
public:
    BinaryBuilder(std::vector<PrimRef>& refs, uint32_t max_leaf, SahCosts costs)
        : refs_(refs), max_leaf_(max_leaf), costs_(costs), nodes_(std::max<std::size_t>(1, 2 * refs.size())) {}

    // Builds the tree over all refs, splitting the top levels on this thread and the subtrees
    // below `parallel_threshold` references as tasks on the pool.
    uint32_t build(ThreadPool& pool) {
        const uint32_t root = allocate();
        std::vector<Task> tasks;
        const uint32_t threshold = std::max<uint32_t>(4096, uint32_t(refs_.size() / 64));
        split_top(root, 0, uint32_t(refs_.size()), 0, threshold, tasks);
        // Largest first, so the two workers finish together.
        std::sort(tasks.begin(), tasks.end(), [](const Task& a, const Task& b) { return a.count > b.count; });
        pool.parallel_for(tasks.size(), [&](std::size_t i, int) {
            const Task& t = tasks[i];
            build_subtree(t.node, t.first, t.count, t.depth);
        });
        return root;
    }

    const BinaryNode& node(uint32_t i) const { return nodes_[i]; }
    uint32_t max_depth() const { return max_depth_.load(); }

private:
    struct Task {
        uint32_t node, first, count, depth;
    };

    uint32_t allocate() { return next_node_.fetch_add(1, std::memory_order_relaxed); }

    void split_top(uint32_t node, uint32_t first, uint32_t count, uint32_t depth, uint32_t threshold, std::vector<Task>& tasks) {
        if (count <= threshold) {
            tasks.push_back({node, first, count, depth});
            return;
        }
        const uint32_t mid = split_or_leaf(node, first, count, depth);
        if (nodes_[node].is_leaf()) return;
        split_top(nodes_[node].left, first, mid - first, depth + 1, threshold, tasks);
        split_top(nodes_[node].right, mid, first + count - mid, depth + 1, threshold, tasks);
    }

    void build_subtree(uint32_t node, uint32_t first, uint32_t count, uint32_t depth) {
        const uint32_t mid = split_or_leaf(node, first, count, depth);
        if (nodes_[node].is_leaf()) return;
        build_subtree(nodes_[node].left, first, mid - first, depth + 1);
        build_subtree(nodes_[node].right, mid, first + count - mid, depth + 1);
    }

    // Makes `node` a leaf over [first, first + count), or partitions the range, allocates the
    // two children and returns where the right one starts.
    uint32_t split_or_leaf(uint32_t node, uint32_t first, uint32_t count, uint32_t depth) {
        BinaryNode& n = nodes_[node];
        Box box, centroids;
        bool one_kind = true;
        for (uint32_t i = first; i < first + count; ++i) {
            box.extend(refs_[i].box);
            centroids.extend_point(refs_[i].box.center());
            one_kind &= refs_[i].kind == refs_[first].kind;
        }
        n.box = box;
        const float leaf_cost = costs_.primitive * float(count);
        const bool may_be_leaf = count <= max_leaf_ && one_kind;
        if (count == 1 || (may_be_leaf && count <= 2)) return make_leaf(n, first, count, depth);

        Split best;
        if (depth < kMaxSahDepth) best = find_sah_split(first, count, centroids, box);
        uint32_t mid;
        if (best.axis >= 0 && (!may_be_leaf || best.cost < leaf_cost)) {
            mid = partition_at(first, count, centroids, best);
        } else if (may_be_leaf) {
            return make_leaf(n, first, count, depth);
        } else if (!one_kind && count <= max_leaf_) {
            // Small but mixed: leaves hold one kind, so split by kind.
            const BvhLeafKind k = refs_[first].kind;
            mid = uint32_t(std::stable_partition(refs_.begin() + first, refs_.begin() + first + count,
                                                 [k](const PrimRef& r) { return r.kind == k; }) -
                           refs_.begin());
        } else {
            mid = median_split(first, count, centroids);
        }
        n.count = 0;
        n.left = allocate();
        n.right = allocate();
        return mid;
    }

    uint32_t make_leaf(BinaryNode& n, uint32_t first, uint32_t count, uint32_t depth) {
        n.first = first;
        n.count = count;
        uint32_t seen = max_depth_.load(std::memory_order_relaxed);
        while (depth + 1 > seen && !max_depth_.compare_exchange_weak(seen, depth + 1)) {
        }
        return first + count;
    }

    static int bin_of(float c, float lo, float scale) {
        const int b = int((c - lo) * scale);
        return std::min(kBins - 1, std::max(0, b));
    }

    Split find_sah_split(uint32_t first, uint32_t count, const Box& centroids, const Box& box) const {
        Bin bins[3][kBins];
        float scale[3];
        for (int a = 0; a < 3; ++a) {
            const float extent = centroids.hi[a] - centroids.lo[a];
            scale[a] = extent > 0.0f ? float(kBins) / extent : 0.0f;
        }
        for (uint32_t i = first; i < first + count; ++i) {
            const PrimRef& r = refs_[i];
            for (int a = 0; a < 3; ++a) {
                Bin& b = bins[a][bin_of(r.centroid(a), centroids.lo[a], scale[a])];
                b.box.extend(r.box);
                ++b.count;
            }
        }
        // Cost of a split, relative to a ray that hits this node: visiting the two children
        // plus testing what each holds, weighted by the chance a ray hitting this box hits theirs.
        Split best;
        const float inv_area = 1.0f / std::max(box.half_area(), std::numeric_limits<float>::min());
        for (int a = 0; a < 3; ++a) {
            if (scale[a] == 0.0f) continue;
            float right_area[kBins];
            uint32_t right_count[kBins];
            Box acc;
            uint32_t n = 0;
            for (int b = kBins - 1; b > 0; --b) {
                acc.extend(bins[a][b].box);
                n += bins[a][b].count;
                right_area[b] = acc.half_area();
                right_count[b] = n;
            }
            acc = Box();
            n = 0;
            for (int b = 1; b < kBins; ++b) {
                acc.extend(bins[a][b - 1].box);
                n += bins[a][b - 1].count;
                if (n == 0 || right_count[b] == 0) continue;
                const float cost = costs_.node + costs_.primitive * inv_area *
                                                     (acc.half_area() * float(n) + right_area[b] * float(right_count[b]));
                if (cost < best.cost) best = {a, b, cost};
            }
        }
        return best;
    }

    uint32_t partition_at(uint32_t first, uint32_t count, const Box& centroids, const Split& s) {
        const float lo = centroids.lo[s.axis];
        const float extent = centroids.hi[s.axis] - lo;
        const float scale = float(kBins) / extent;
        const int axis = s.axis, split = s.bin;
        auto it = std::partition(refs_.begin() + first, refs_.begin() + first + count,
                                 [&](const PrimRef& r) { return bin_of(r.centroid(axis), lo, scale) < split; });
        return uint32_t(it - refs_.begin());
    }

    // Half by centroid order along the widest centroid axis; ties in order of scene id, so the
    // result does not depend on how the range happened to be arranged.
    uint32_t median_split(uint32_t first, uint32_t count, const Box& centroids) {
        int axis = 0;
        for (int a = 1; a < 3; ++a)
            if (centroids.hi[a] - centroids.lo[a] > centroids.hi[axis] - centroids.lo[axis]) axis = a;
        const uint32_t mid = first + count / 2;
        std::nth_element(refs_.begin() + first, refs_.begin() + mid, refs_.begin() + first + count,
                         [axis](const PrimRef& a, const PrimRef& b) {
                             const float ca = a.centroid(axis), cb = b.centroid(axis);
                             return ca < cb || (ca == cb && a.id < b.id);
                         });
        return mid;
    }

    std::vector<PrimRef>& refs_;
    const uint32_t max_leaf_;
    const SahCosts costs_;
    std::vector<BinaryNode> nodes_;
    std::atomic<uint32_t> next_node_{0};
    std::atomic<uint32_t> max_depth_{0};
};

// ---- Primitive boxes --------------------------------------------------------------------------

bool never_hit(const TriangleSoA& t, std::size_t i) {
    // Slivers are stored collapsed onto their first vertex (geometry_soa.h): no test hits them.
    return t.e1x[i] == 0.0f && t.e1y[i] == 0.0f && t.e1z[i] == 0.0f && t.e2x[i] == 0.0f && t.e2y[i] == 0.0f &&
           t.e2z[i] == 0.0f;
}

std::vector<PrimRef> primitive_refs(const Scene& scene) {
    const TriangleSoA& t = scene.triangles;
    const SphereSoA& s = scene.spheres;
    std::vector<PrimRef> refs;
    refs.reserve(t.size() + s.size());
    for (std::size_t i = 0; i < t.size(); ++i) {
        if (never_hit(t, i)) continue;
        PrimRef r;
        r.id = uint32_t(i);
        r.kind = t.is_parallelogram(i) ? BvhLeafKind::parallelogram : BvhLeafKind::triangle;
        // The corners as the tests see them: v0 + u e1 + v e2 over the triangle or the unit
        // square, and the vertices the watertight test reads.
        r.box.extend_point(t.vertex0(i));
        r.box.extend_point(t.vertex1(i));
        r.box.extend_point(t.vertex2(i));
        r.box.extend_point(t.vertex0(i) + t.edge1(i));
        r.box.extend_point(t.vertex0(i) + t.edge2(i));
        if (r.kind == BvhLeafKind::parallelogram) r.box.extend_point(t.vertex0(i) + t.edge1(i) + t.edge2(i));
        refs.push_back(r);
    }
    for (std::size_t i = 0; i < s.size(); ++i) {
        PrimRef r;
        r.id = uint32_t(t.size() + i);
        r.kind = BvhLeafKind::sphere;
        const glm::vec3 c = s.center(i);
        const glm::vec3 radius(s.radius[i]);
        r.box.extend_point(c - radius);
        r.box.extend_point(c + radius);
        refs.push_back(r);
    }
    return refs;
}

// ---- Collapse into wide nodes, primitives into leaf order ------------------------------------

class WideCollapser {
public:
    WideCollapser(const Scene& scene, const BinaryBuilder& tree, const std::vector<PrimRef>& refs, float pad, int width,
                  AlignedVector<BvhNode<4>>& nodes4, AlignedVector<BvhNode<8>>& nodes8, BvhPrimitives& leaves)
        : scene_(scene), tree_(tree), refs_(refs), pad_(pad), width_(width), nodes4_(nodes4), nodes8_(nodes8), leaves_(leaves) {}

    uint32_t emit(uint32_t binary) {
        const BinaryNode& b = tree_.node(binary);
        if (b.is_leaf()) return emit_leaf(b);
        return width_ == 4 ? emit_inner<4>(b, nodes4_) : emit_inner<8>(b, nodes8_);
    }

    double node_area_sum = 0.0, leaf_cost_sum = 0.0;
    std::size_t leaf_count = 0;

private:
    template <int W>
    uint32_t emit_inner(const BinaryNode& b, AlignedVector<BvhNode<W>>& nodes) {
        // Open the child with the largest surface area until there are W (Embree's collapse):
        // the children most rays enter are the ones worth testing together.
        uint32_t children[W];
        int n = 2;
        children[0] = b.left;
        children[1] = b.right;
        while (n < W) {
            int widest = -1;
            float widest_area = -1.0f;
            for (int c = 0; c < n; ++c) {
                const BinaryNode& child = tree_.node(children[c]);
                if (!child.is_leaf() && child.box.half_area() > widest_area) widest = c, widest_area = child.box.half_area();
            }
            if (widest < 0) break;
            const BinaryNode& open = tree_.node(children[widest]);
            children[widest] = open.left;
            children[n++] = open.right;
        }
        const uint32_t index = uint32_t(nodes.size());
        nodes.emplace_back();
        node_area_sum += b.box.half_area();
        for (int c = 0; c < W; ++c) {
            for (int row = 0; row < 6; ++row) nodes[index].bounds[row][c] = (row & 1) ? -kInf : kInf;
            nodes[index].child[c] = kBvhEmptyChild;
        }
        for (int c = 0; c < n; ++c) {
            const BinaryNode& child = tree_.node(children[c]);
            const uint32_t ref = emit(children[c]);  // may reallocate `nodes`: index it afresh
            BvhNode<W>& node = nodes[index];
            const Box padded = child.box.padded(pad_);
            for (int a = 0; a < 3; ++a) {
                node.bounds[2 * a][c] = padded.lo[a];
                node.bounds[2 * a + 1][c] = padded.hi[a];
            }
            node.child[c] = ref;
        }
        return index;
    }

    uint32_t emit_leaf(const BinaryNode& b) {
        const BvhLeafKind kind = refs_[b.first].kind;
        const uint32_t first = kind == BvhLeafKind::sphere ? leaves_.sphere_count() : leaves_.planar_count();
        if (first + b.count > kBvhMaxLeafPrimitives)
            throw std::invalid_argument("BVH: more than " + std::to_string(kBvhMaxLeafPrimitives) +
                                        " primitives of one kind; the node format cannot index them");
        for (uint32_t i = b.first; i < b.first + b.count; ++i) leaves_.append(scene_, refs_[i].id);
        ++leaf_count;
        leaf_cost_sum += double(b.box.half_area()) * b.count;
        return kBvhLeafBit | (uint32_t(kind) << kBvhKindShift) | ((b.count - 1) << kBvhCountShift) | first;
    }

    static constexpr float kInf = std::numeric_limits<float>::infinity();
    const Scene& scene_;
    const BinaryBuilder& tree_;
    const std::vector<PrimRef>& refs_;
    const float pad_;
    const int width_;
    AlignedVector<BvhNode<4>>& nodes4_;
    AlignedVector<BvhNode<8>>& nodes8_;
    BvhPrimitives& leaves_;
};

}  // namespace

Bvh build_bvh(const Scene& scene, const BvhBuildOptions& options, ThreadPool* pool) {
    if (options.node_width != 4 && options.node_width != 8)
        throw std::invalid_argument("BVH: node width must be 4 or 8, got " + std::to_string(options.node_width));
    if (options.max_leaf_size < 1 || options.max_leaf_size > int(kBvhMaxLeafSize))
        throw std::invalid_argument("BVH: leaf size must be 1 ... 8, got " + std::to_string(options.max_leaf_size));
    const auto start = std::chrono::steady_clock::now();
    std::unique_ptr<ThreadPool> own_pool;
    if (!pool) {
        const int threads = options.threads > 0 ? options.threads : int(std::max(1u, std::thread::hardware_concurrency()));
        own_pool = std::make_unique<ThreadPool>(threads);
        pool = own_pool.get();
    }

    Bvh bvh;
    bvh.node_width_ = options.node_width;
    std::vector<PrimRef> refs = primitive_refs(scene);
    bvh.primitives_.test = scene.settings.accuracy.triangles;
    if (!refs.empty()) {
        Box scene_box;
        for (const PrimRef& r : refs) scene_box.extend(r.box);
        const float pad = rounding_pad(scene_box, scene.camera.eye());
        BinaryBuilder tree(refs, uint32_t(options.max_leaf_size), SahCosts{});
        const uint32_t root = tree.build(*pool);
        WideCollapser collapse(scene, tree, refs, pad, options.node_width, bvh.nodes4_, bvh.nodes8_, bvh.primitives_);
        bvh.root_ = collapse.emit(root);
        bvh.stats_.max_depth = tree.max_depth();
        // The wide tree is no deeper than the binary one it was collapsed from.
        if (tree.max_depth() * uint32_t(options.node_width - 1) + 1 > uint32_t(kBvhStackSize))
            throw std::invalid_argument("BVH: tree too deep for the traversal stack (" + std::to_string(tree.max_depth()) + " levels)");
        bvh.stats_.leaf_count = collapse.leaf_count;
        const double root_area = std::max(double(tree.node(root).box.half_area()), 1e-30);
        bvh.stats_.sah_cost = (collapse.node_area_sum + collapse.leaf_cost_sum) / root_area;
    }
    bvh.stats_.primitive_count = refs.size();
    bvh.stats_.node_count = options.node_width == 4 ? bvh.nodes4_.size() : bvh.nodes8_.size();
    bvh.stats_.node_bytes = bvh.nodes4_.size() * sizeof(BvhNode<4>) + bvh.nodes8_.size() * sizeof(BvhNode<8>);
    bvh.stats_.primitive_bytes = bvh.primitives_.bytes();
    bvh.stats_.build_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return bvh;
}

}  // namespace wt

namespace wt {

BvhView bvh_view(const Bvh& bvh) {
    BvhView v;
    v.node_width = uint32_t(bvh.node_width_);
    v.nodes = bvh.node_width_ == 4 ? static_cast<const void*>(bvh.nodes4_.data()) : static_cast<const void*>(bvh.nodes8_.data());
    v.root = bvh.root_;
    v.max_depth = bvh.stats_.max_depth;
    v.planar = bvh.primitives_.planar_view();
    v.spheres = bvh.primitives_.sphere_view();
    v.planar_prim = bvh.primitives_.planar_prim.data();
    v.sphere_prim = bvh.primitives_.sphere_prim.data();
    return v;
}

}  // namespace wt
