#pragma once
// Which acceleration structure a render traces against. "Model only what the scene requires":
// a scene of a few dozen primitives is fastest as a flat list (every ray tests every primitive,
// with no traversal and no tree to build); past the crossover the BVH's logarithmic cost wins.

#include <cstdint>
#include <optional>
#include <string>

namespace wt {

enum class Accel {
    automatic,  // brute force below kBvhCrossoverPrimitives primitives, else a BVH
    bvh,
    brute,      // the flat list: every ray against every primitive
};

// Measured with `wavetrace render` on the hexroom plus meshes of growing size (bench/README.md):
// below this many primitives the flat ray-packet kernels render faster than the BVH.
constexpr uint32_t kBvhCrossoverPrimitives = 64;

const char* accel_name(Accel accel);
std::optional<Accel> parse_accel(const std::string& name);  // "auto", "bvh", "brute"

// What `automatic` resolves to for a scene of `primitives` primitives.
inline Accel resolve_accel(Accel requested, uint32_t primitives) {
    if (requested != Accel::automatic) return requested;
    return primitives < kBvhCrossoverPrimitives ? Accel::brute : Accel::bvh;
}

}  // namespace wt
