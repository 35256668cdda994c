#pragma once
// The kernels' view (soa_views.h) of a TriangleSoA: its arrays' pointers, null for the rows the
// scene's triangle test does not store. Out of line, for the plain-struct rule of soa_views.h.

#include "core/geometry/geometry_soa.h"
#include "kernels/primitives/soa_views.h"

namespace wt {

TriangleView triangle_view(const TriangleSoA& t);

}  // namespace wt
