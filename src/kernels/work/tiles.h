#pragma once
// The image cut into square tiles, the unit of work a worker takes. Tiles are listed in
// scanline order; the last column and row may be narrower.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace wt {

struct Tile {
    int x0, y0, x1, y1;  // pixels [x0, x1) x [y0, y1)
    int pixel_count() const { return (x1 - x0) * (y1 - y0); }
};

// Some of a tile's pixels (image indices, in scanline order): adaptive sampling's pixels still
// sampled (kernels/adaptive/).
struct TilePixels {
    const uint32_t* index = nullptr;
    std::size_t count = 0;
};

inline std::vector<Tile> make_tiles(int width, int height, int tile_size) {
    std::vector<Tile> tiles;
    for (int y = 0; y < height; y += tile_size)
        for (int x = 0; x < width; x += tile_size)
            tiles.push_back({x, y, std::min(x + tile_size, width), std::min(y + tile_size, height)});
    return tiles;
}

}  // namespace wt
