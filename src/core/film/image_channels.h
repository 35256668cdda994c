#pragma once
// Named channels of an image, their values interleaved per pixel, rows top to bottom: the
// AOV layers a render writes into EXR files.

#include <string>
#include <vector>

namespace wt {

struct ImageChannels {
    std::vector<std::string> names;
    std::vector<float> values;  // pixel count * names.size()
};

}  // namespace wt
