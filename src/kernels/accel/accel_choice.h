#pragma once
// Which acceleration structure a render traces against. "Model only what the scene requires":
// a scene of a few dozen primitives is fastest as a flat list (every ray tests every primitive,
// with no traversal and no tree to build); past the crossover the BVH's logarithmic cost wins.

#include <cstdint>
#include <optional>
#include <string>

namespace wt {

enum class Accel {
    automatic,  // brute force below bvh_crossover() primitives, else a BVH
    bvh,
    brute,      // the flat list: every ray against every primitive
};
inline constexpr Accel kAllAccels[] = {Accel::automatic, Accel::bvh, Accel::brute};

// The flat ray-packet kernels test as many rays at once as they have lanes, so how many
// primitives they beat a BVH on depends on the width, and not only through it: the 4-lane
// kernels test an 8-wide node in two halves, so their tree gains least. Measured per width with
// `wavetrace render` on the hexroom plus a UV-sphere mesh of growing size (bench/README.md,
// "The crossover"): the number of primitives at which both renders take equally long.
inline uint32_t bvh_crossover(int kernel_width) {
    switch (kernel_width) {
        case 4: return 88;
        case 8: return 72;
        case 16: return 150;
        default: return 20;  // the scalar kernels
    }
}

// Whether the tree leaves a scene's few parallelograms (a room's walls, floor and lights) out, to
// be tested beside it (BvhView::beside): by kernels with lanes to test several at once, where
// the wall a ray hits, found first, bounds its walk. The scalar kernels would test them one by
// one; for them the tree, which skips most, is faster (bench/README.md, issue 18).
inline bool parallelograms_beside_tree(int kernel_width) { return kernel_width > 1; }

// Header-only, as isa.h's names: the command-line code parses them without linking the kernels.
inline const char* accel_name(Accel accel) {
    switch (accel) {
        case Accel::automatic: return "auto";
        case Accel::bvh: return "bvh";
        case Accel::brute: return "brute";
    }
    return "unknown";
}

// accel_name of one of kAllAccels; empty for anything else.
inline std::optional<Accel> parse_accel(const std::string& name) {
    for (Accel a : kAllAccels)
        if (name == accel_name(a)) return a;
    return std::nullopt;
}

// What `automatic` resolves to for a scene of `primitives` primitives traced by kernels of
// `kernel_width` lanes. Instances are traced through their two-level BVH only, and so are
// alpha-tested materials (the alpha test is in the BVH's walk, kernels/accel/alpha_filter.h):
// with either, `automatic` is the BVH (and `brute` is refused by the renderer).
inline Accel resolve_accel(Accel requested, uint32_t primitives, int kernel_width, bool bvh_only = false) {
    if (requested != Accel::automatic) return requested;
    if (bvh_only) return Accel::bvh;
    return primitives < bvh_crossover(kernel_width) ? Accel::brute : Accel::bvh;
}

}  // namespace wt
