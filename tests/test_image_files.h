#pragma once
// Image files written byte by byte, without the image module, so tests of what reads them share
// no code with it: a binary PGM (one grey channel) and an uncompressed 32-bit TGA (RGBA), both
// top row first, every row alike (value(x) of column x).

#include <array>
#include <cstdint>
#include <functional>
#include <string>

namespace wt::test {

// width x height; every row alike, value(x) at column x.
inline std::string pgm(int width, int height, const std::function<uint8_t(int)>& value) {
    std::string bytes = "P5\n" + std::to_string(width) + " " + std::to_string(height) + "\n255\n";
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) bytes.push_back(char(value(x)));
    return bytes;
}
inline std::string tga_rgba(int width, int height, const std::function<std::array<uint8_t, 4>(int)>& rgba) {
    std::string bytes(18, '\0');
    bytes[2] = 2;  // uncompressed true colour
    bytes[12] = char(width & 0xff), bytes[13] = char(width >> 8), bytes[14] = char(height & 0xff), bytes[15] = char(height >> 8);
    bytes[16] = 32, bytes[17] = 0x28;  // 8 alpha bits, top row first
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const std::array<uint8_t, 4> c = rgba(x);
            for (int i : {2, 1, 0, 3}) bytes.push_back(char(c[std::size_t(i)]));  // BGRA
        }
    return bytes;
}

}  // namespace wt::test
