// The shade kernels at width 8, compiled with the avx2 target flags (src/kernels/CMakeLists.txt).
#include "kernels/isa/shade_kernels.h"
#include "kernels/shading/area_light_rays.h"
#include "kernels/shading/diffuse_continuation.h"
#include "kernels/shading/diffuse_light_samples.h"
#include "kernels/shading/diffuse_random.h"
#include "kernels/shading/light_points.h"
#include "kernels/shading/specular_continuation.h"
#include "kernels/shading/surface_points.h"

namespace wt {

const ShadeKernels kShadeAvx2 = {Isa::avx2, 8, &shading::surface_points<8>, &shading::continue_diffuse_vertices<8>,
                                 &shading::draw_diffuse_random, &shading::pick_light_points<8>,
                                 &shading::sample_diffuse_lights<8>, &shading::aim_area_light_rays<8>,
                                 &shading::continue_specular_vertices<8>};

}  // namespace wt
