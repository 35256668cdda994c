#pragma once
// Textures the texture tests build in code: width x height texels from texel(x, y), stored as
// given (a data texture unless `srgb`).

#include <memory>

#include "core/textures/texture_image.h"

namespace wt::test {

template <typename F>
TextureImage texture_of(int width, int height, F texel, TextureWrap wrap = TextureWrap::repeat, bool srgb = false) {
    auto texels = std::make_shared<TextureTexels>();
    texels->width = width, texels->height = height;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) texels->rgba.push_back(texel(x, y));
    TextureImage image;
    image.name = "generated";
    image.texels = texels;
    image.srgb = srgb;
    image.wrap_s = image.wrap_t = wrap;
    return image;
}

}  // namespace wt::test
