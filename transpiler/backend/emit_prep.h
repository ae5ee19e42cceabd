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
// GLSL declares gl_InvocationID as int; HLSL's SV_OutputControlPointID and SV_GSInstanceID are
// uint, and glslang keeps the uint input. SPIRV-Cross converts it where an int is needed but not
// where a uint is (`uint id = gl_InvocationID;`, which needs GLSL 4.00's implicit conversions and
// never compiles in ESSL): for a GLSL/ESSL output the input becomes an int, each load converted
// back, so the text reads `uint(gl_InvocationID)`. (The other built-ins HLSL makes uint,
// SV_PrimitiveID, SV_SampleIndex, SV_VertexID, ..., SPIRV-Cross converts itself.)
void signIntegerBuiltIns(spirv::Module& module);
// Legacy GLSL (before 1.30) and ESSL 1.00 write a fragment's colours through gl_FragColor /
// gl_FragData[n], which are vec4: SPIRV-Cross assigns a float, vec2 or vec3 output to them as it
// is, which does not compile. Each such output becomes a vec4, its stores padded with 0 and an alpha
// of 1 (the components the shader never wrote; a colour attachment's are undefined then), its loads
// taking the first components back. An output used any other way is left alone.
void widenLegacyFragmentOutputs(spirv::Module& module);

}  // namespace stereoshift
