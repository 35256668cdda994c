// The shade kernels at width 4, compiled with the sse4 target flags (src/kernels/CMakeLists.txt).
#include "kernels/isa/shade_kernels.h"
#include "kernels/shading/area_light_rays.h"
#include "kernels/shading/diffuse_continuation.h"
#include "kernels/shading/diffuse_light_samples.h"
#include "kernels/shading/diffuse_random.h"
#include "kernels/shading/light_points.h"
#include "kernels/shading/specular_continuation.h"
#include "kernels/shading/surface_points.h"

namespace wt {

const ShadeKernels kShadeSse4 = {Isa::sse4, 4, &shading::surface_points<4>, &shading::continue_diffuse_vertices<4>,
                                 &shading::draw_diffuse_random, &shading::pick_light_points<4>,
                                 &shading::sample_diffuse_lights<4>, &shading::aim_area_light_rays<4>,
                                 &shading::continue_specular_vertices<4>};

}  // namespace wt
