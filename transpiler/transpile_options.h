// The options of one conversion: each layer's part (FrontEndOptions, PassOptions, BackEndOptions),
// which each layer reads alone; the driver and the command line hold all three.
#pragma once

#include "passes/pass_options.h"
#include "transpiler/backend/back_end_options.h"
#include "transpiler/frontend/front_end_options.h"

#include <cstdint>
#include <optional>
#include <string>

namespace stereoshift {

// What the compilation units of one stage say by their text, for the text route (a stage OpenGL
// links from several shader objects, each in the pipeline).
struct StageUnits {
  // Another unit assigns gl_Position: a unit whose `main` only calls into the others still gets
  // the shift around its `main`.
  bool otherWritesPosition = false;
  // Every other unit keeps gl_Position's w the literal 1 (textKeepsUnitW): with this unit's text,
  // the stage's 2D proof.
  bool othersKeepUnitW = true;
  // A geometry stage: one of its units (this one or another) calls EmitVertex / EmitStreamVertex.
  bool stageEmits = true;
  // A stage of several units none of which names gl_Position: it writes no clip position.
  bool noUnitNamesPosition = false;
};

struct TranspileOptions : FrontEndOptions, PassOptions, BackEndOptions {
  // A pipeline holds another compilation unit of this stage (OpenGL links a stage from several
  // shader objects): a unit that does not link alone may be one of them (stage_plan.h).
  bool stageHasOtherUnits = false;
  // What the stage's other units say by their text (text_only_shift.h reads it where glslang
  // cannot analyse the stage).
  StageUnits units;
};

// The eye parameters from 3Dmigoto's StereoParams texture (t125), as 3Dmigoto fills it
// (--eye-source 3dmigoto, and a dump's default): the passes analyse with a cbuffer of an internal
// name in its place (so that the dump's own `StereoParams` declaration is no clash), the HLSL splice
// renders the texture, and the fixes only the dump's text can carry are recorded for it.
// Layout numbers written into emitted text must fit glslang's layout fields (it re-compiles the text):
// the largest of each, and the option's error for a value past it (the conversion options and
// `reproject`'s alike).
constexpr uint64_t kMaxDescriptorSet = 62, kMaxBinding = 65534, kMaxSpecId = 2046, kMaxLocation = 4094;
inline std::optional<std::string> layoutNumberOutOfRange(const char* option, uint64_t value, uint64_t max) {
  if (value <= max) return std::nullopt;
  return std::string(option) + " " + std::to_string(value) + " is out of range (valid: 0 to " + std::to_string(max) + ")";
}

inline void readEyeParamsFrom3DMigoto(TranspileOptions& options) {
  options.eyeFrom3DMigoto = true;
  options.eye.source = EyeSource::UniformBlock;
  options.sourceTextFixes = true;
  if (options.eye.blockName == "StereoParams") options.eye.blockName = "stereoshift_StereoParams";
}

}  // namespace stereoshift
