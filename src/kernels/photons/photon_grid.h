#pragma once
// One sample's photons in a hashed uniform grid, for fixed-radius lookups: the idea of pbrt-v4's
// SPPM integrator (src/pbrt/cpu/integrators.cpp, SPPMIntegrator::Render), whose grid hashes
// the integer coordinates of a cell into a table of as many buckets as entries, so that memory
// follows the photons, not the scene's extent. There the camera's visible points are in the
// grid and each photon looks them up; here the photons are, and each camera vertex looks them
// up, which lets a sample's camera paths be shaded in any order once its photons are in.
//
// Built by a counting sort on the bucket: the photons of a bucket stay in the order they were
// given (light path key order), so the grid is the same bits however the light paths were
// scheduled and however many threads build it. Cells are a little over twice the radius wide, so
// a lookup's sphere overlaps at most two cells per axis: eight buckets.
//
// A render builds one grid per sample, of megabytes each: build() reuses the grid's arrays, so a
// sample's build neither faults in fresh pages nor zeroes memory it then overwrites.

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/geometric.hpp>

#include "kernels/photons/photon.h"

namespace wt {

class ThreadPool;

class PhotonGrid {
public:
    PhotonGrid() = default;
    // The photons of `parts`, concatenated in order; `radius` finite and positive.
    PhotonGrid(const std::vector<const PhotonList*>& parts, float radius) { build(parts, radius); }
    // The same grid, in this grid's memory (what it held before is gone); with the pool's
    // threads if given (never from inside one of its jobs).
    void build(const std::vector<const PhotonList*>& parts, float radius, ThreadPool* pool = nullptr);

    float radius() const { return radius_; }
    std::size_t size() const { return photons_.size(); }

    // visit(photon, index) for every photon within the radius of x (squared distance <=
    // radius^2, in float), each once; `index` is its place in the concatenated input. The order
    // is the grid's, not the index's: a caller that sums must sum exactly (photon_gather.h).
    template <typename Visit>
    void for_each_within(const glm::vec3& x, Visit&& visit) const {
        if (photons_.empty()) return;
        uint64_t buckets[8];
        int count = 0;
        const double reach = double(radius_) * kLookupMargin;
        const int64_t lo[3] = {cell_of(double(x.x) - reach), cell_of(double(x.y) - reach), cell_of(double(x.z) - reach)};
        const int64_t hi[3] = {cell_of(double(x.x) + reach), cell_of(double(x.y) + reach), cell_of(double(x.z) + reach)};
        for (int64_t cz = lo[2]; cz <= hi[2]; ++cz)
            for (int64_t cy = lo[1]; cy <= hi[1]; ++cy)
                for (int64_t cx = lo[0]; cx <= hi[0]; ++cx) {
                    const uint64_t b = bucket_of(cx, cy, cz);
                    bool seen = false;  // two cells hashed to one bucket: its photons once
                    for (int k = 0; k < count; ++k) seen |= buckets[k] == b;
                    if (!seen) buckets[count++] = b;
                }
        for (int k = 0; k < count; ++k)
            for (uint32_t i = start_[buckets[k]], end = start_[buckets[k] + 1]; i < end; ++i) {
                const glm::vec3 v = photons_[i].position - x;
                if (glm::dot(v, v) <= radius_squared_) visit(photons_[i], index_[i]);
            }
    }

private:
    // A cell is 2 r (1 + 2^-10) wide and a lookup covers r (1 + 2^-11) about its point: at most
    // two cells per axis, and a photon the float distance test accepts (its rounding is far below
    // 2^-11 r) is always in a cell it covers.
    static constexpr double kCellMargin = 1.0 + 0x1p-10, kLookupMargin = 1.0 + 0x1p-11;

    int64_t cell_of(double coordinate) const;
    uint64_t bucket_of(int64_t cx, int64_t cy, int64_t cz) const;
    uint64_t bucket_of(const glm::vec3& p) const { return bucket_of(cell_of(p.x), cell_of(p.y), cell_of(p.z)); }

    float radius_ = 0.0f, radius_squared_ = 0.0f;
    double inverse_cell_ = 0.0;
    uint64_t mask_ = 0;                // buckets - 1 (a power of two)
    PhotonList photons_;                    // by bucket, each bucket's in input order
    UninitialisedVector<uint32_t> index_;   // each one's place in the input
    UninitialisedVector<uint32_t> start_;   // bucket b's photons are [start_[b], start_[b + 1])
    UninitialisedVector<uint32_t> bucket_;  // the build's: each input photon's bucket
    UninitialisedVector<uint32_t> next_;    // the build's: each bucket's count, then its next free place
};

}  // namespace wt
