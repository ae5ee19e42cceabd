// The HLSL splice's rendering of the shift: turns a ShiftSpec into HLSL text, the cbuffer of the
// eye parameters and one helper function per shifted type, `T stereoshift_shift_T(T v)`, that
// shifts the SV_Position of v the way the SPIR-V route's emitters do (passes/shift_emitter.h):
// the same guard, the same operations in the same order, `precise` where they are NoContraction.
#pragma once

#include "transpiler/backend/hlsl_splice.h"

#include <string>
#include <vector>

namespace stereoshift::hlsl_splice {

// The prefix of every name the splice declares.
constexpr const char* kPrefix = "stereoshift";

// One helper to declare.
struct ShiftHelper {
  std::string type;      // HLSL type of the helper parameter/return
  std::string function;  // helper name
  std::string access;    // member path inside the value, e.g. ".Position" ("" for a float4)
  // Further float4 members that hold an exact copy of the clip position (halo copies: the passes
  // found them equal to it), shifted the same way from their own x and w.
  std::vector<std::string> copies;
  // Whether `access` itself is shifted (false with --corrections-only: the copies only).
  bool positionToo = true;
};

// The cbuffer of the eye parameters.
std::string cbufferText(const HlslSpliceOptions& options, const std::string& nl);

// A float as an HLSL literal that reads back as the same float (`0.5f`, `1.0f`, `1e-05f`).
std::string floatLiteral(float value);

// `T function(T v) { ...shift v<access>.x... return v; }` for one helper.
std::string shiftFunctionText(const HlslSpliceOptions& spec, const ShiftHelper& helper, const std::string& nl);

// The whole injected block: a banner, the cbuffer and every helper, lines ending in `nl`.
std::string preambleText(const HlslSpliceOptions& options, const std::vector<ShiftHelper>& helpers,
                         const std::string& nl);

}  // namespace stereoshift::hlsl_splice
