#pragma once
// The two questions a ray asks of the scene. Traversal and primitive loops are written once and
// take the query as a template argument.

#include <cstdint>
#include <type_traits>

#include "kernels/primitives/soa_views.h"

namespace wt {

enum class Query {
    closest,  // the nearest hit with t in (0, tmax): distance, primitive, barycentrics
    any,      // whether anything lies at t in (0, tmax); may stop at the first blocker
};

// Where a query's answers go: hit records, or one occlusion flag (0 or 1) per ray.
template <Query Q>
using QueryOutput = std::conditional_t<Q == Query::closest, const HitView&, uint8_t*>;

}  // namespace wt
