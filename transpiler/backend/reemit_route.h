// The re-emit route: SPIRV-Cross writes GLSL / ESSL / HLSL / MSL from the converted module, with the
// repairs that make it a drop-in (back_end.h). Takes every stage the other routes decline.
#pragma once

#include "transpiler/backend/route.h"

#include <memory>

namespace stereoshift {

std::unique_ptr<BackEndRoute> createReemitRoute();

}  // namespace stereoshift
