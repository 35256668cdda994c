#pragma once
// A texture as the shade stage reads it: linear RGBA levels, level 0 the image and each next one
// half the size (rounded down, at least 1), a box filter of the one before (Williams 1983's
// pyramid), looked up bilinearly within a level and linearly between two (texture_lookup.h).
// Our own layout rather than OpenImageIO's TextureSystem: README, "Textures", says why.

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
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
    std::size_t level_count() const { return levels_ ? levels_->size() : 0; }
    const MipLevel& level(std::size_t i) const { return (*levels_)[i]; }
    TextureWrap wrap_s() const { return wrap_s_; }
    TextureWrap wrap_t() const { return wrap_t_; }
    // 0.5 log2(width * height) of level 0, plus the transform's 0.5 log2 |det|: the texture's
    // term of the ray cone's level of detail.
    float log2_texel_scale() const { return log2_texel_scale_; }
    int coordinate_set() const { return coordinate_set_; }  // TextureImage::coordinate_set
    // A hit's coordinates through the texture's transform (TextureImage::offset, ...); the same
    // bits without one.
    glm::vec2 transformed(glm::vec2 uv) const {
        if (!transformed_) return uv;
        return {row0_.x * uv.x + row0_.y * uv.y + row0_.z, row1_.x * uv.x + row1_.y * uv.y + row1_.z};
    }
    std::size_t bytes() const;

private:
    std::string name_;
    // Shared by copies: the light table keeps its emitters' textures (core/lights/light_table.h)
    // without a second copy of their texels, and without pointing into the scene.
    std::shared_ptr<const std::vector<MipLevel>> levels_;
    TextureWrap wrap_s_ = TextureWrap::repeat, wrap_t_ = TextureWrap::repeat;
    float log2_texel_scale_ = 0.0f;
    int coordinate_set_ = 0;
    bool transformed_ = false;
    glm::vec3 row0_{1.0f, 0.0f, 0.0f}, row1_{0.0f, 1.0f, 0.0f};  // the affine map's two rows
};

}  // namespace wt
