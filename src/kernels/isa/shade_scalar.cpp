// The shade kernels at width 1, compiled with the scalar target flags (src/kernels/CMakeLists.txt).
#include "kernels/isa/shade_kernels.h"
#include "kernels/shading/area_light_rays.h"
#include "kernels/shading/diffuse_continuation.h"
#include "kernels/shading/diffuse_light_samples.h"
#include "kernels/shading/diffuse_random.h"
#include "kernels/shading/light_points.h"
#include "kernels/shading/specular_continuation.h"
#include "kernels/shading/surface_points.h"

namespace wt {

const ShadeKernels kShadeScalar = {Isa::scalar, 1, &shading::surface_points<1>, &shading::continue_diffuse_vertices<1>,
                                   &shading::draw_diffuse_random, &shading::pick_light_points<1>,
                                   &shading::sample_diffuse_lights<1>, &shading::aim_area_light_rays<1>,
                                   &shading::continue_specular_vertices<1>};

}  // namespace wt
