// The options the back end reads: the output language and version, and how it writes it.
#pragma once

#include "core/shader.h"

#include <optional>

namespace stereoshift {

struct BackEndOptions {
  TargetLanguage target = TargetLanguage::Auto;
  std::optional<int> targetVersion;  // GLSL/ESSL version or HLSL shader model (50, 51, 60, ...)
  bool verify = false;               // recompile emitted GLSL/HLSL with glslang
  bool forceReemit = false;          // re-emit even when nothing changed
  // --require-analysis: a stage glslang cannot parse is an error, never shifted from its text alone
  // (text_only_shift.h).
  bool requireAnalysis = false;
  // --unchecked-text-route: the routes that say yes where glslang did not (the text-only shift, the
  // unanalysed copy, the lifted copy's splice) are taken without Mesa's word when no Mesa is at hand
  // (frontend/mesa_compiler.h), said in the report; without it they are refused then.
  bool uncheckedTextRoute = false;
  // --eye-source 3dmigoto: the eye parameters are 3Dmigoto's `StereoParams` texture at t125
  // (texel 0: x separation with the eye's sign, y convergence), rendered by the HLSL source splice
  // only; the passes analyse with an internal cbuffer in its place.
  bool eyeFrom3DMigoto = false;
  // verify only: the SPIR-V goes to verify's harness, which repairs what glslang's module gets
  // wrong for OpenGL GLSL (a loose `uniform bool`, see convertOpenGLForVulkan) before it runs it, so the
  // SPIR-V routes write a module that does not validate for that reason instead of refusing it.
  bool spirvForHarness = false;
};

}  // namespace stereoshift
