#pragma once
// The speed-for-accuracy switches. Each default is the classic fast choice; each alternative
// costs a measured amount (README, "Accuracy options") and buys robustness at the extremes.

#include <cstdint>
#include <optional>
#include <string>

namespace wt {

enum class TriangleTest : uint8_t {
    moller_trumbore,  // Moller & Trumbore 1997: fast; rays through shared edges can slip through
    watertight,       // Woop, Benthin & Wald 2013: no ray escapes between adjacent triangles
};

enum class SphereTest : uint8_t {
    quadratic,          // textbook b^2 - c: loses digits for small or distant spheres
    cancellation_free,  // Ray Tracing Gems ch. 7: discriminant from the closest-approach vector
};

enum class FresnelModel : uint8_t {
    schlick,  // Schlick 1994 approximation
    exact,    // the dielectric Fresnel equations (average of s and p polarisations)
};

// What becomes of the light a GGX lobe sends into a second microfacet (rough conductors and
// the principled material's specular lobe; core/materials/multiple_scattering.h).
enum class MultipleScattering : uint8_t {
    none,         // single scattering, as the glTF specification's BRDF: the rougher, the more is lost
    kulla_conty,  // Kulla & Conty 2017: a lobe giving back what single scattering loses
};

struct AccuracySettings {
    TriangleTest triangles = TriangleTest::moller_trumbore;
    SphereTest spheres = SphereTest::quadratic;
    FresnelModel fresnel = FresnelModel::schlick;
    MultipleScattering multiple_scattering = MultipleScattering::none;
};

const char* name_of(TriangleTest);
const char* name_of(SphereTest);
const char* name_of(FresnelModel);
const char* name_of(MultipleScattering);
std::optional<TriangleTest> parse_triangle_test(const std::string&);
std::optional<SphereTest> parse_sphere_test(const std::string&);
std::optional<FresnelModel> parse_fresnel_model(const std::string&);
std::optional<MultipleScattering> parse_multiple_scattering(const std::string&);

}  // namespace wt
