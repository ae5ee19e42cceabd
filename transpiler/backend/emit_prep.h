// What the back end does to a copy of the converted module before SPIRV-Cross sees it: drop the
// qualifiers glslang had to auto-assign (OpenGL shaders keep relying on glBindAttribLocation & co.),
// and read the interface facts SPIRV-Cross loses (HLSL semantics, cbuffer member names).
#pragma once

#include "passes/ir/module.h"
#include "core/shader.h"
#include "transpiler/backend/back_end.h"

namespace stereoshift {

void stripAutoAssignedQualifiers(spirv::Module& module, const SourceInfo& info);
EmitHints collectHints(const spirv::Module& module);

}  // namespace stereoshift
