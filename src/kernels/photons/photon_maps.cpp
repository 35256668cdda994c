#include "kernels/photons/photon_maps.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace wt {

struct PhotonMaps::Slot {
    float radius = 0.0f;
    std::once_flag built;
};

PhotonMaps::PhotonMaps(const Scene& scene)
    : initial_radius_(initial_photon_radius(scene)), schedule_(initial_radius_) {}

PhotonMaps::~PhotonMaps() = default;

uint32_t PhotonMaps::samples_per_batch(uint64_t batch_paths, uint64_t light_paths_per_sample) {
    return uint32_t(std::clamp<uint64_t>(batch_paths / std::max<uint64_t>(1, light_paths_per_sample), 1, 1u << 20));
}

void PhotonMaps::start_batch(uint32_t begin, uint32_t end, uint64_t items_per_sample) {
    if (end <= begin) throw std::invalid_argument("PhotonMaps: an empty batch");
    begin_ = begin, end_ = end, items_per_sample_ = items_per_sample;
    const std::size_t items = std::size_t(items_per_sample) * (end - begin);
    if (items_.size() < items) items_.resize(items);
    for (std::size_t i = 0; i < items; ++i) items_[i].clear();
    slots_.clear();
    if (grids_.size() < end - begin) grids_.resize(end - begin);
    for (uint32_t s = begin; s < end; ++s) {
        auto slot = std::make_unique<Slot>();
        slot->radius = float(std::sqrt(schedule_.squared(s)));
        slots_.push_back(std::move(slot));
    }
}

void PhotonMaps::end_batch() {
    asked_before_ = asked_.exchange(false, std::memory_order_relaxed);
    slots_.clear();
    begin_ = end_ = 0;
}

void PhotonMaps::release() {
    end_batch();
    std::vector<PhotonList>().swap(items_);
    std::vector<PhotonGrid>().swap(grids_);
}

const PhotonGrid& PhotonMaps::map(uint32_t sample) const {
    if (!has_sample(sample)) throw std::logic_error("PhotonMaps: a sample outside the batch");
    // Read before written: the flag's cache line is written once a batch, not once a lookup.
    if (!asked_.load(std::memory_order_relaxed)) asked_.store(true, std::memory_order_relaxed);
    return build(sample, nullptr);
}

void PhotonMaps::build_if_asked_before(ThreadPool& pool) {
    if (!asked_before_) return;
    for (uint32_t s = begin_; s < end_; ++s) build(s, &pool);
}

const PhotonGrid& PhotonMaps::build(uint32_t sample, ThreadPool* pool) const {
    Slot& slot = *slots_[sample - begin_];
    PhotonGrid& grid = grids_[sample - begin_];
    std::call_once(slot.built, [&] {
        std::vector<const PhotonList*> parts;
        const std::size_t first = std::size_t(items_per_sample_) * (sample - begin_);
        for (std::size_t i = first; i < first + items_per_sample_; ++i) parts.push_back(&items_[i]);
        grid.build(parts, slot.radius, pool);
        maps_built_.fetch_add(1, std::memory_order_relaxed);
    });
    return grid;
}

}  // namespace wt
