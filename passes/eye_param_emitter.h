// The eye-parameter emitter: the one way any pass declares and loads the eye parameters (as NIR's
// builder serves every pass). The eye-params pass asks it for the first three in a shader that gets
// the shift; hud-at-depth, per-eye-view and deferred-unprojection ask for more (see EyeParam) when
// they need them, also in shaders that get no shift.
#pragma once

#include "passes/ir/module.h"

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace stereoshift {

struct PassContext;

// Declares the eye parameters 0..count-1 (see EyeParam) if they are not declared yet, or extends
// the declared ones up to `count`, and records them (RunRecord::eyeParams). False (with an error in
// the context's diagnostics) when they cannot be declared.
bool ensureEyeParams(PassContext& context, int count);

// Appends instructions to `out` that load eye parameter `which` (an EyeParam, declared through
// ensureEyeParams) and returns the id of the loaded float. In the single-pass modes eyeSign is
// derived per view or instance instead (eye_select.h).
uint32_t emitLoadEyeParam(PassContext& context, std::vector<spirv::Instruction>& out, int which);

// The name an injected declaration takes when `wanted` is taken: wanted, wanted2, wanted3, ... (the
// eye block and its instance here, the text-only HLSL shift's cbuffer).
std::string numberedName(const std::string& wanted, const std::function<bool(const std::string&)>& taken);

}  // namespace stereoshift
