#pragma once
// A texture as the shade stage reads it: linear RGBA levels, level 0 the image and each next one
// half the size (rounded down, at least 1), a box filter of the one before (Williams 1983's
// pyramid), looked up bilinearly within a level and linearly between two (texture_lookup.h).
// Our own layout rather than OpenImageIO's TextureSystem: README, "Textures", says why.

#include <cstddef>
#include <string>
#include <vector>

#include <glm/vec4.hpp>

#include "core/textures/texture_image.h"

namespace wt {

struct MipLevel {
    int width = 0, height = 0;
    std::vector<glm::vec4> texels;  // rows top to bottom

    const glm::vec4& at(int x, int y) const { return texels[std::size_t(y) * std::size_t(width) + std::size_t(x)]; }
};

// One level down: each texel the mean of the source texels its footprint covers, partly covered
// ones weighted by the fraction covered, so odd (non-power-of-two) sizes filter without a shift.
MipLevel box_downsample(const MipLevel& source);

class MipPyramid {
public:
    MipPyramid() = default;
    // Decodes sRGB (image.srgb) and builds every level down to 1 x 1.
    explicit MipPyramid(const TextureImage& image);

    const std::string& name() const { return name_; }
    std::size_t level_count() const { return levels_.size(); }
    const MipLevel& level(std::size_t i) const { return levels_[i]; }
    TextureWrap wrap_s() const { return wrap_s_; }
    TextureWrap wrap_t() const { return wrap_t_; }
    // 0.5 log2(width * height) of level 0: the texture's term of the ray cone's level of detail.
    float log2_texel_scale() const { return log2_texel_scale_; }
    std::size_t bytes() const;

private:
    std::string name_;
    std::vector<MipLevel> levels_;
    TextureWrap wrap_s_ = TextureWrap::repeat, wrap_t_ = TextureWrap::repeat;
    float log2_texel_scale_ = 0.0f;
};

}  // namespace wt
