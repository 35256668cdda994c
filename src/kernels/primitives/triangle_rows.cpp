#include "kernels/primitives/triangle_rows.h"

#include <stdexcept>

namespace wt {
namespace {

void push3(AlignedVector<float>& x, AlignedVector<float>& y, AlignedVector<float>& z, const glm::vec3& v) {
    x.push_back(v.x), y.push_back(v.y), z.push_back(v.z);
}

void push_entry(TriangleRows& r, const TriangleSoA& t, std::size_t i) {
    push3(r.v0x, r.v0y, r.v0z, t.vertex0(i));
    push3(r.e1x, r.e1y, r.e1z, t.edge1(i));
    push3(r.e2x, r.e2y, r.e2z, t.edge2(i));
    if (t.has_scaled_normal()) push3(r.scaled_nx, r.scaled_ny, r.scaled_nz, t.scaled_normal(i));
    if (t.has_vertices()) push3(r.v1x, r.v1y, r.v1z, t.vertex1(i)), push3(r.v2x, r.v2y, r.v2z, t.vertex2(i));
    ++r.count;
    if (t.is_parallelogram(i)) {
        if (r.parallelogram_count + 1 != r.count) throw std::logic_error("triangle_rows: a parallelogram after a triangle");
        ++r.parallelogram_count;
    }
}

}  // namespace

TriangleRows triangle_rows(const TriangleSoA& t, std::size_t count) {
    if (count > t.size()) throw std::logic_error("triangle_rows: more entries than stored");
    TriangleRows r;
    for (std::size_t i = 0; i < count; ++i) push_entry(r, t, i);
    return r;
}

TriangleRows triangle_rows(const TriangleSoA& t, const std::vector<uint32_t>& entries) {
    TriangleRows r;
    for (const uint32_t i : entries) {
        if (i >= t.size()) throw std::logic_error("triangle_rows: an entry past the end");
        push_entry(r, t, i);
    }
    return r;
}

TriangleView triangle_view(const TriangleRows& t) {
    return {t.v0x.data(),       t.v0y.data(),       t.v0z.data(),       t.e1x.data(), t.e1y.data(), t.e1z.data(),
            t.e2x.data(),       t.e2y.data(),       t.e2z.data(),       t.scaled_nx.data(), t.scaled_ny.data(),
            t.scaled_nz.data(), t.v1x.data(),       t.v1y.data(),       t.v1z.data(), t.v2x.data(), t.v2y.data(),
            t.v2z.data(),       t.count,            t.parallelogram_count};
}

}  // namespace wt
