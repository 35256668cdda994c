#pragma once
// A basic that reaches up to the scene: the edge the check must catch.
#include "core/scene/scene.h"
#include "core/base/missing.h"
struct Ray {};
