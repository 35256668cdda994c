#pragma once
// Finds and loads the image I/O module (see image_module_abi.h) the first time an image is
// read, or written in a format it writes: libwavetrace_image_io.so in the directory of the running executable, where
// the build and `cmake --install` put it.

#include <string>

#include "core/image_io/image_error.h"
#include "core/image_io/image_module_abi.h"

namespace wt {

// Where the module is looked for.
std::string image_module_path();

// The loaded module. Thread-safe; loads once. Throws ImageError saying what is missing (the
// path, the loader's message, or a module of another ABI version) on every call until it loads.
const WtImageModuleApi& image_module();

}  // namespace wt
