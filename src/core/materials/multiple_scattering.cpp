#include "core/materials/multiple_scattering.h"

namespace wt {

glm::vec3 exact_fresnel_average(const ConductorFresnel& fresnel) {
    // The midpoint rule on 2 F(mu) mu over [0, 1]: F is smooth in mu (steepest at grazing, where
    // mu weighs it least), so 1024 points leave an error far below float's.
    constexpr int n = 1024;
    glm::dvec3 sum(0.0);
    for (int i = 0; i < n; ++i) {
        const float mu = (float(i) + 0.5f) / float(n);
        sum += glm::dvec3(fresnel(mu)) * double(mu);
    }
    return glm::vec3(sum * (2.0 / n));
}

}  // namespace wt
