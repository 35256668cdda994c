#include "kernels/photons/photon_grid.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/sampling/rng.h"
#include "core/system/thread_pool.h"

namespace wt {

void PhotonGrid::build(const std::vector<const PhotonList*>& parts, float radius, ThreadPool* pool) {
    if (!(radius > 0.0f && std::isfinite(radius * radius)))
        throw std::invalid_argument("PhotonGrid: the radius must be positive and its square finite");
    radius_ = radius, radius_squared_ = radius * radius, inverse_cell_ = 1.0 / (2.0 * double(radius) * kCellMargin);
    std::vector<std::size_t> first(parts.size() + 1, 0);  // part k's photons are [first[k], first[k + 1])
    for (std::size_t k = 0; k < parts.size(); ++k) first[k + 1] = first[k] + parts[k]->size();
    const std::size_t n = first.back();
    if (n > UINT32_MAX) throw std::length_error("PhotonGrid: more than 2^32 - 1 photons in one sample");
    uint64_t buckets = 1;
    while (buckets < n) buckets *= 2;
    mask_ = buckets - 1;
    // Sized from empty: a vector that must grow then moves nothing. Every entry is written below.
    const auto resize_unwritten = [](auto& v, std::size_t size) {
        if (v.capacity() < size) v.clear();
        v.resize(size);
    };
    resize_unwritten(bucket_, n);
    resize_unwritten(photons_, n);
    resize_unwritten(index_, n);
    resize_unwritten(start_, std::size_t(buckets) + 1);
    resize_unwritten(next_, std::size_t(buckets));
    const bool threads = pool && pool->thread_count() > 1;
    const auto run = [&](std::size_t jobs, const auto& job) {
        if (threads && jobs > 1) pool->parallel_for(jobs, [&](std::size_t k, int) { job(k); });
        else for (std::size_t k = 0; k < jobs; ++k) job(k);
    };

    // A counting sort on the bucket. Each photon's bucket, part by part.
    run(parts.size(), [&](std::size_t k) {
        uint32_t* bucket = bucket_.data() + first[k];
        for (const Photon& p : *parts[k]) *bucket++ = uint32_t(bucket_of(p.position));
    });
    // Then the buckets in `ranges` contiguous ranges, a job each: the job counts its buckets'
    // photons and places them, reading every photon's bucket in input order and keeping those in
    // its range, so each bucket's photons stay in input order whatever the ranges: the grid is
    // the same bits for any thread count. Each job reads all n buckets, so one range per thread.
    const std::size_t ranges = threads ? std::size_t(std::min<uint64_t>(buckets, uint64_t(pool->thread_count()))) : 1;
    const auto range = [&](std::size_t r) {
        return std::pair<uint64_t, uint64_t>(buckets * r / ranges, buckets * (r + 1) / ranges);
    };
    std::vector<uint32_t> range_start(ranges + 1, 0);
    run(ranges, [&](std::size_t r) {
        const auto [lo, hi] = range(r);
        std::fill(next_.begin() + lo, next_.begin() + hi, 0u);
        for (std::size_t i = 0; i < n; ++i)
            if (bucket_[i] - lo < hi - lo) ++next_[bucket_[i]];  // (unsigned: lo <= bucket < hi)
        uint32_t at = 0;  // the buckets' starts within the range's photons
        for (uint64_t b = lo; b < hi; ++b) start_[b] = at, at += next_[b];
        range_start[r + 1] = at;
    });
    for (std::size_t r = 0; r < ranges; ++r) range_start[r + 1] += range_start[r];
    start_[buckets] = uint32_t(n);
    run(ranges, [&](std::size_t r) {
        const auto [lo, hi] = range(r);
        for (uint64_t b = lo; b < hi; ++b) next_[b] = start_[b] += range_start[r];
        std::size_t i = 0;
        for (const auto* part : parts)
            for (const Photon& p : *part) {
                if (bucket_[i] - lo < hi - lo) {
                    const uint32_t at = next_[bucket_[i]]++;
                    photons_[at] = p;
                    index_[at] = uint32_t(i);
                }
                ++i;
            }
    });
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
