// The shade kernels at width 16, compiled with the avx512 target flags (src/kernels/CMakeLists.txt).
#include "kernels/isa/shade_kernels.h"
#include "kernels/shading/area_light_rays.h"
#include "kernels/shading/diffuse_continuation.h"
#include "kernels/shading/diffuse_light_samples.h"
#include "kernels/shading/diffuse_random.h"
#include "kernels/shading/light_points.h"
#include "kernels/shading/specular_continuation.h"
#include "kernels/shading/surface_points.h"

namespace wt {

const ShadeKernels kShadeAvx512 = {Isa::avx512, 16, &shading::surface_points<16>, &shading::continue_diffuse_vertices<16>,
                                   &shading::draw_diffuse_random, &shading::pick_light_points<16>,
                                   &shading::sample_diffuse_lights<16>, &shading::aim_area_light_rays<16>,
                                   &shading::continue_specular_vertices<16>};

}  // namespace wt
