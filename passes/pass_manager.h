// The pass pipeline: a plain list, in order, with the reason for each position.
#pragma once

#include "passes/pass.h"

namespace stereoshift {

// Runs the passes on ctx.module. Returns false when a pass failed (diagnostics say why).
// `changed` reports whether any pass changed the module.
bool runPassPipeline(PassContext& ctx, bool* changed, std::string* passLog);

}  // namespace stereoshift
