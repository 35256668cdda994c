#pragma once
// The photon maps of a small batch of consecutive samples: sample s's map holds the photons of
// sample s's light paths (photon.h) at radius r_s (photon_radius.h). The render traces a
// batch's light paths (light tracing's pass, which also splats them), shades the batch's camera
// paths, then clears the batch: memory follows one batch's photons, never the render's.
//
// The light paths of one work item of the light tracing pass write their photons to that item's
// list (photons(item)), so the lists need no lock and, read in item order, are in light path
// key order. A sample's grid is built from its items' lists the first time a camera path asks
// for it, by whichever thread asks first (the others wait): a batch no camera path sees through
// a mirror or glass builds nothing, and the grid is the same bits whoever builds it. Once a
// batch's camera paths have asked, the next batch's grids are built before its camera paths, by
// all the threads (build_if_asked_before): they will be asked for too, and then no thread waits.

#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <vector>

#include "core/scene/scene.h"
#include "kernels/photons/photon.h"
#include "kernels/photons/photon_grid.h"
#include "kernels/photons/photon_radius.h"

namespace wt {

class ThreadPool;

class PhotonMaps {
public:
    explicit PhotonMaps(const Scene& scene);
    ~PhotonMaps();

    // Samples per batch for a batch of at most `batch_paths` light paths (RenderOptions::
    // photon_batch_paths; a photon is 52 bytes, and a light path leaves a few at most), at least 1.
    static uint32_t samples_per_batch(uint64_t batch_paths, uint64_t light_paths_per_sample);

    // Empties the maps and makes room for samples [begin, end), `items_per_sample` photon lists each.
    void start_batch(uint32_t begin, uint32_t end, uint64_t items_per_sample);
    // Ends the batch; its photon lists and grids keep their memory for the next batch's.
    void end_batch();
    // Frees everything (at the end of a range of samples).
    void release();

    // The photon list of the batch's work item `item` (sample begin + item / items_per_sample).
    PhotonList& photons(std::size_t item) { return items_[item]; }

    // Sample `sample`'s map (which must be in the batch), built on first use; thread-safe.
    const PhotonGrid& map(uint32_t sample) const;
    // Builds the batch's maps now, with the pool's threads, if the camera paths of the batch
    // before asked for a map; call between the batch's light paths and its camera paths.
    void build_if_asked_before(ThreadPool& pool);
    bool has_sample(uint32_t sample) const { return sample >= begin_ && sample < end_; }
    // How many maps were built since construction (tests: "no photon work").
    uint64_t maps_built() const { return maps_built_.load(std::memory_order_relaxed); }

private:
    struct Slot;
    // Sample `sample`'s map, built by the first call (with the pool's threads if given).
    const PhotonGrid& build(uint32_t sample, ThreadPool* pool) const;

    double initial_radius_;
    PhotonRadiusSchedule schedule_;
    uint32_t begin_ = 0, end_ = 0;
    uint64_t items_per_sample_ = 0;
    std::vector<PhotonList> items_;
    std::vector<std::unique_ptr<Slot>> slots_;  // one per sample of the batch
    // Sample begin_ + i's grid is grids_[i], rebuilt in place each batch (photon_grid.h); written
    // only under its slot's once_flag.
    mutable std::vector<PhotonGrid> grids_;
    mutable std::atomic<uint64_t> maps_built_{0};
    mutable std::atomic<bool> asked_{false};  // some camera path asked this batch for a map
    bool asked_before_ = false;               // ... the batch before this one
};

}  // namespace wt
