// The SPIR-V printer of the shift (core/shift_spec.h): a ShiftSpec is made once from the options;
// the IR emitters below render it as instructions (the stereo-shift and halo passes, so the position
// and its halo copies are shifted by exactly the same sequence, bit for bit). The text printers
// render the same spec (the GLSL and HLSL splices, D3D assembly).
#pragma once

#include "passes/ir/module.h"
#include "passes/pass_options.h"
#include "core/shader.h"
#include "core/shift_spec.h"

#include <cstdint>
#include <string>
#include <vector>

namespace stereoshift {

struct PassContext;

// The spec the options ask for. `preciseSupported`: whether the output language can express
// NoContraction (see targetSupportsPrecise); names are the configured ones.
ShiftSpec makeShiftSpec(const PassOptions& options, bool preciseSupported);

// The spec of this conversion: the options, the target's `precise`, and the eye parameter names as
// declared (after clash resolution) once eye-params has run.
ShiftSpec shiftSpec(const PassContext& context);

// Whether the emitted language can express NoContraction (`precise`).
bool targetSupportsPrecise(const PassContext& context);

// The two pieces every stereo fix is built from, for already loaded eye parameters (loaded through
// eye_param_emitter.h).
// `eyeSign != 0` (unordered: only an exact zero is mono); the zero constant is made after the id.
uint32_t emitStereoGuard(PassContext& context, std::vector<spirv::Instruction>& out, uint32_t eyeSign);
// `eyeSign * separation`, NoContraction when `noContraction`.
uint32_t emitEyeScale(PassContext& context, std::vector<spirv::Instruction>& out, uint32_t eyeSign,
                      uint32_t separation, bool noContraction = false);

// Appends `x + eyeSign*separation*(w - convergence)` for the float ids `x` and `w` in the form the
// spec asks for (plain, fused or compensated); returns its id.
uint32_t emitShiftedX(PassContext& context, const ShiftSpec& spec, std::vector<spirv::Instruction>& out, uint32_t x,
                      uint32_t w);
uint32_t emitShiftedX(PassContext& context, std::vector<spirv::Instruction>& out, uint32_t x, uint32_t w);

// Appends the condition under which `w` is shifted (a bool id): eyeSign != 0, and unless the cutoff
// is off, |w - 1| > epsilon (or w != 1) and w finite.
uint32_t emitCutoffCondition(PassContext& context, const ShiftSpec& spec, std::vector<spirv::Instruction>& out,
                             uint32_t w);
uint32_t emitCutoffCondition(PassContext& context, std::vector<spirv::Instruction>& out, uint32_t w);

// Returns a vec4 id: `value` with x shifted, selected by the cutoff (branch-free; used for halo copies).
uint32_t emitShiftedVec4Select(PassContext& context, std::vector<spirv::Instruction>& out, uint32_t value);

}  // namespace stereoshift
