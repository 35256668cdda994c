#pragma once
// Material name -> index into the scene's materials, kept up to date as materials are appended
// (a mesh file adds its own). Shapes name their material, so a linear scan per shape made a
// scene of 50k materials and 50k shapes take 16 s to load.

#include <cstdint>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "core/description/scene_description.h"

namespace wt {

class MaterialNames {
public:
    // `materials` must outlive this; it may grow.
    explicit MaterialNames(const std::vector<Material>& materials) : materials_(materials) {}

    // The index of the first material of that name, as a scan from the front would find it.
    std::optional<uint32_t> find(const std::string& name) {
        for (; indexed_ < materials_.size(); ++indexed_) index_.emplace(materials_[indexed_].name, uint32_t(indexed_));
        const auto it = index_.find(name);
        if (it == index_.end()) return std::nullopt;
        return it->second;
    }

private:
    const std::vector<Material>& materials_;
    std::unordered_map<std::string, uint32_t> index_;
    std::size_t indexed_ = 0;
};

}  // namespace wt
