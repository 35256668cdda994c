#include "kernels/accel/accel_choice.h"

namespace wt {

const char* accel_name(Accel accel) {
    switch (accel) {
        case Accel::automatic: return "auto";
        case Accel::bvh: return "bvh";
        case Accel::brute: return "brute";
    }
    return "unknown";
}

std::optional<Accel> parse_accel(const std::string& name) {
    for (Accel a : kAllAccels)
        if (name == accel_name(a)) return a;
    return std::nullopt;
}

}  // namespace wt
