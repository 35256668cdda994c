#pragma once
// The one exception the scene loader throws: its message is complete and meant for the user.

#include <stdexcept>

namespace wt {

// what() is the complete message for the user: "SOURCE: FIELD.PATH: problem, got VALUE",
// or "SOURCE:LINE:COLUMN: JSON syntax error: ..." when the text is not JSON at all.
struct SceneError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

}  // namespace wt
