// The options of one conversion: each layer's part (FrontEndOptions, PassOptions, BackEndOptions),
// which each layer reads alone; the driver and the command line hold all three.
#pragma once

#include "passes/pass_options.h"
#include "transpiler/backend/back_end_options.h"
#include "transpiler/frontend/front_end_options.h"

namespace stereoshift {

struct TranspileOptions : FrontEndOptions, PassOptions, BackEndOptions {
  // A pipeline holds another compilation unit of this stage (OpenGL links a stage from several
  // shader objects): a unit that does not link alone may be one of them (stage_plan.h).
  bool stageHasOtherUnits = false;
};

}  // namespace stereoshift
