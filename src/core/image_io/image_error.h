#pragma once
// The one error type of image reading and writing: its message names the file.

#include <stdexcept>

namespace wt {

struct ImageError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

}  // namespace wt
