#include "core/base/accuracy.h"

#include "core/base/enum_names.h"

namespace wt {

const char* name_of(TriangleTest t) { return t == TriangleTest::watertight ? "watertight" : "moller_trumbore"; }
const char* name_of(SphereTest s) { return s == SphereTest::cancellation_free ? "cancellation_free" : "quadratic"; }
const char* name_of(FresnelModel f) { return f == FresnelModel::exact ? "exact" : "schlick"; }
const char* name_of(MultipleScattering m) { return m == MultipleScattering::kulla_conty ? "kulla_conty" : "none"; }

std::optional<TriangleTest> parse_triangle_test(const std::string& s) {
    return parse_one_of(s, {TriangleTest::moller_trumbore, TriangleTest::watertight});
}
std::optional<SphereTest> parse_sphere_test(const std::string& s) {
    return parse_one_of(s, {SphereTest::quadratic, SphereTest::cancellation_free});
}
std::optional<FresnelModel> parse_fresnel_model(const std::string& s) {
    return parse_one_of(s, {FresnelModel::schlick, FresnelModel::exact});
}

std::optional<MultipleScattering> parse_multiple_scattering(const std::string& s) {
    return parse_one_of(s, {MultipleScattering::none, MultipleScattering::kulla_conty});
}

}  // namespace wt
