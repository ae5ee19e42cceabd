// The eye of the single-pass modes (--eye-source multiview | instanced): where eyeSign comes from
// when it is not a parameter, and the interface that carries it between stages.
//   multiview: the view index (gl_ViewIndex / gl_ViewID_OVR / SV_ViewID), view 0 the left eye;
//   instanced: the low bit of the instance index in the vertex stage (the application doubles the
//     instance count); every later stage reads the varying `stereoEye` the stage before it wrote (the
//     fragment stage too, also for OpenGL multiview, where SPIRV-Cross writes gl_ViewID_OVR in vertex
//     shaders only). Between pre-rasterization stages it is `stereoEyeStage`, through tessellation
//     `patch out int stereoEyePatch` (every vertex of a patch comes from one instance); tessellation
//     control and geometry stages read element 0 of their per-vertex input array.
// The eye-parameter emitter derives eyeSign here (emitDerivedEyeSign); the single-pass-stereo pass
// declares and routes what this file describes.
#pragma once

#include "passes/ir/module.h"
#include "passes/pass_options.h"
#include "core/shader.h"

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace stereoshift {

struct PassContext;

// eyeSign in the single-pass modes: appends the instructions that derive it per view or instance
// (exactly -1.0 or +1.0, the values a two-pass draw sets) and returns the float id.
uint32_t emitDerivedEyeSign(PassContext& ctx, std::vector<spirv::Instruction>& out);

bool glslOutput(TargetLanguage t);
// The output language, as the back end will resolve it (Auto: the input's own).
TargetLanguage outputLanguage(const PassContext& ctx);
// Whether a GLSL/ESSL output has OpenGL (not Vulkan) semantics, as the back end decides it.
bool openGlOutput(const PassContext& ctx, TargetLanguage target);
// The GLSL/ESSL version the output will have.
int glslOutputVersion(const PassContext& ctx, TargetLanguage target);
const char* modeFlag(EyeSelect select);

uint32_t builtInVariable(const spirv::Module& m, spv::BuiltIn builtIn);
// A fresh 32-bit int interface variable, named like the GLSL built-in so the emitted text reads as
// the application's own would.
uint32_t addIntVariable(spirv::Module& m, spv::StorageClass storage, std::string_view name, bool isSigned = true);
// The view index, declared when the shader reads none.
uint32_t ensureViewIndex(PassContext& ctx);
// The instance index the shader reads (gl_InstanceIndex, OpenGL's gl_InstanceID, HLSL's
// SV_InstanceID), declared when it reads none: InstanceId for OpenGL GLSL, InstanceIndex elsewhere.
uint32_t ensureInstanceIndex(PassContext& ctx);
// Whether an interface variable of `storage` already takes `location` (a clash with stereoEye): a
// variable whose locations (a matrix, an array, a struct take several) cover it, or a block member
// placed there. `who` names it.
bool locationTaken(const spirv::Module& m, spv::StorageClass storage, uint32_t location, std::string* who);
// The name of the eye varying on one side of a stage: `stereoEye` (--eye-varying-name) into the
// fragment stage, `stereoEyeStage` between two pre-rasterization stages, `stereoEyePatch` per patch.
std::string eyeVaryingName(const PassContext& ctx, spv::StorageClass storage);
// The eye varying of this stage (`storage` Input: what the stage before wrote, Output: what this
// stage hands on), declared on first use at --eye-varying-location. 0 (with an error) when another
// variable already takes the location.
uint32_t ensureEyeVarying(PassContext& ctx, spv::StorageClass storage);
uint32_t emitLoad(spirv::Module& m, std::vector<spirv::Instruction>& out, uint32_t variable);
// `instance & 1`: the eye of an instanced-stereo vertex (0 for instances 0, 2, 4, ...).
uint32_t emitInstanceEyeBit(PassContext& ctx, std::vector<spirv::Instruction>& out);
// Loads the eye the stage before wrote into this stage's `stereoEye` input (element 0 of a
// per-vertex array). 0 on a location clash.
uint32_t emitLoadHandedOnEye(PassContext& ctx, std::vector<spirv::Instruction>& out);

}  // namespace stereoshift
