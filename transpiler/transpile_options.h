// The options of one conversion: each layer's part (FrontEndOptions, PassOptions, BackEndOptions),
// which each layer reads alone; the driver and the command line hold all three.
#pragma once

#include "passes/pass_options.h"
#include "transpiler/backend/back_end_options.h"
#include "transpiler/frontend/front_end_options.h"

namespace stereoshift {

struct TranspileOptions : FrontEndOptions, PassOptions, BackEndOptions {};

}  // namespace stereoshift
