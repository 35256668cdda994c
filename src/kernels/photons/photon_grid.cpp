#include "kernels/photons/photon_grid.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/sampling/rng.h"

namespace wt {

void PhotonGrid::build(const std::vector<const PhotonList*>& parts, float radius) {
    if (!(radius > 0.0f && std::isfinite(radius * radius)))
        throw std::invalid_argument("PhotonGrid: the radius must be positive and its square finite");
    radius_ = radius, radius_squared_ = radius * radius, inverse_cell_ = 1.0 / (2.0 * double(radius) * kCellMargin);
    std::size_t n = 0;
    for (const auto* part : parts) n += part->size();
    if (n > UINT32_MAX) throw std::length_error("PhotonGrid: more than 2^32 - 1 photons in one sample");
    uint64_t buckets = 1;
    while (buckets < n) buckets *= 2;
    mask_ = buckets - 1;
    // Sized from empty: a vector that must grow then moves nothing.
    const auto resize_unwritten = [](auto& v, std::size_t size) {
        if (v.capacity() < size) v.clear();
        v.resize(size);
    };
    // Counting sort: each photon's bucket, the buckets' sizes, their starts, then every photon
    // in input order to the next place in its bucket.
    resize_unwritten(bucket_, n);
    start_.assign(std::size_t(buckets) + 1, 0);
    std::size_t i = 0;
    for (const auto* part : parts)
        for (const Photon& p : *part) ++start_[(bucket_[i++] = uint32_t(bucket_of(p.position))) + 1];
    for (std::size_t b = 0; b < buckets; ++b) start_[b + 1] += start_[b];
    next_.assign(start_.begin(), start_.end() - 1);
    resize_unwritten(photons_, n);
    resize_unwritten(index_, n);
    i = 0;
    for (const auto* part : parts)
        for (const Photon& p : *part) {
            const uint32_t at = next_[bucket_[i]]++;
            photons_[at] = p;
            index_[at] = uint32_t(i++);
        }
}

int64_t PhotonGrid::cell_of(double coordinate) const {
    // Clamped far beyond any cell a finite scene's photons reach at a sane radius; at an absurd
    // one, distant cells share a coordinate, which only costs lookups distance tests.
    const double c = std::floor(coordinate * inverse_cell_);
    return int64_t(std::clamp(c, -0x1p52, 0x1p52));
}

uint64_t PhotonGrid::bucket_of(int64_t cx, int64_t cy, int64_t cz) const {
    return mix64(mix64(mix64(uint64_t(cx)) + uint64_t(cy)) + uint64_t(cz)) & mask_;
}

}  // namespace wt
