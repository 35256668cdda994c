#pragma once
#include "core/base/ray.h"
#include <vector>
struct Scene { std::vector<Ray> rays; };
