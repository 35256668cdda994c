#pragma once
// The binary SAH tree laid out as W-wide nodes (bvh_view.h), shared by the scene's tree and the
// instances' top level. Internal to the builders.

#include <cstdint>
#include <limits>
#include <vector>

#include "core/base/aligned_vector.h"
#include "kernels/accel/bvh_boxes.h"
#include "kernels/accel/bvh_view.h"
#include "kernels/accel/sah_builder.h"

namespace wt {

// Lays the binary tree out as W-wide nodes in depth-first order from the root, and lists the
// leaves for fill_leaf_blocks.
template <int W>
class WideCollapser {
public:
    WideCollapser(const BinaryTree& tree, float pad, AlignedVector<BvhNode<W>>& nodes) : tree_(tree), pad_(pad), nodes_(nodes) {}

    uint32_t emit(uint32_t binary) {
        const BinaryNode& b = tree_.nodes[binary];
        return b.is_leaf() ? emit_leaf(b) : emit_inner(b);
    }

    // Sums for the SAH cost of the result: node boxes' areas, leaf areas times their counts.
    double node_area_sum = 0.0, leaf_area_sum = 0.0;
    std::vector<uint32_t> leaves;  // their references (bvh_view.h), in the order they were met

private:
    uint32_t emit_inner(const BinaryNode& b) {
        // Open the child with the largest surface area until there are W (as Embree's BVH4/8
        // builders do): the children most rays enter are the ones worth testing together.
        uint32_t children[W];
        int n = 2;
        children[0] = b.left;
        children[1] = b.right;
        while (n < W) {
            int widest = -1;
            float widest_area = -1.0f;
            for (int c = 0; c < n; ++c) {
                const BinaryNode& child = tree_.nodes[children[c]];
                const float area = child.box().half_area();
                if (!child.is_leaf() && area > widest_area) widest = c, widest_area = area;
            }
            if (widest < 0) break;
            const BinaryNode& open = tree_.nodes[children[widest]];
            children[widest] = open.left;
            children[n++] = open.right;
        }
        const uint32_t index = uint32_t(nodes_.size());
        nodes_.emplace_back();
        node_area_sum += b.box().half_area();
        for (int c = 0; c < W; ++c) {
            for (int row = 0; row < 6; ++row) nodes_[index].bounds[row][c] = (row & 1) ? -kInf : kInf;
            nodes_[index].child[c] = kBvhEmptyChild;
        }
        for (int c = 0; c < n; ++c) {
            const uint32_t ref = emit(children[c]);  // may reallocate nodes_: index it afresh
            const Box padded = tree_.nodes[children[c]].box().padded(pad_);
            BvhNode<W>& node = nodes_[index];
            for (int a = 0; a < 3; ++a) {
                node.bounds[2 * a][c] = padded.lo_at(a);
                node.bounds[2 * a + 1][c] = padded.hi_at(a);
            }
            node.child[c] = ref;
        }
        return index;
    }

    // The leaf's primitives keep their place in the references (the partitions made each leaf a
    // contiguous run there), so the blocks can be filled later, in parallel (fill_leaf_blocks).
    uint32_t emit_leaf(const BinaryNode& b) {
        leaf_area_sum += double(b.box().half_area()) * b.count;
        leaves.push_back(kBvhLeafBit | (b.leaf_kind << kBvhKindShift) | ((b.count - 1) << kBvhCountShift) | b.first);
        return leaves.back();
    }

    static constexpr float kInf = std::numeric_limits<float>::infinity();
    const BinaryTree& tree_;
    const float pad_;
    AlignedVector<BvhNode<W>>& nodes_;
};

}  // namespace wt
