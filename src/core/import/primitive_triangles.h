#pragma once
// A glTF primitive's vertex sequence as triangles, for the three modes that have a surface,
// as the glTF 2.0 specification defines them (3.7.2.1, "Topology types"): fed one vertex at a
// time, so the indices need not be copied out of their buffer first.

#include <array>
#include <cstdint>
#include <vector>

namespace wt {

enum class PrimitiveMode { triangles = 4, triangle_strip = 5, triangle_fan = 6 };

class PrimitiveTriangles {
public:
    PrimitiveTriangles(PrimitiveMode mode, std::vector<std::array<uint32_t, 3>>& out) : mode_(mode), out_(out) {}

    void push(uint32_t v) {
        switch (mode_) {
        case PrimitiveMode::triangles:  // p_i = {v_3i, v_3i+1, v_3i+2}
            corner_[n_ % 3] = v;
            if (n_ % 3 == 2) out_.push_back(corner_);
            break;
        case PrimitiveMode::triangle_strip:
            // p_i = {v_i, v_i+(1+i%2), v_i+(2-i%2)}: every odd triangle has its last two corners
            // swapped, so that all of the strip's triangles face the same way.
            if (n_ >= 2) out_.push_back((n_ - 2) % 2 == 0 ? std::array<uint32_t, 3>{a_, b_, v} : std::array<uint32_t, 3>{a_, v, b_});
            a_ = b_;
            b_ = v;
            break;
        case PrimitiveMode::triangle_fan:  // p_i = {v_i+1, v_i+2, v_0}
            if (n_ == 0) a_ = v;
            if (n_ >= 2) out_.push_back({b_, v, a_});
            b_ = v;
            break;
        }
        ++n_;
    }

private:
    PrimitiveMode mode_;
    std::vector<std::array<uint32_t, 3>>& out_;
    std::size_t n_ = 0;                 // vertices pushed so far
    std::array<uint32_t, 3> corner_{};  // triangles: the current one
    uint32_t a_ = 0, b_ = 0;            // strip: the last two vertices; fan: the first and the last
};

}  // namespace wt
