#include "core/system/version.h"

namespace wt {

// A compile definition on this file alone (src/core/CMakeLists.txt), so a new version
// recompiles one file.
const char* program_version() { return WAVETRACE_VERSION; }

}  // namespace wt
