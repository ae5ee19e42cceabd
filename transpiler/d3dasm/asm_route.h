// The assembly route of the driver: this turns a D3D shader-assembly input (the disassembly
// 3Dmigoto dumps as `<hash>-vs.txt`) into its converted text and report, without the front end,
// the passes or SPIRV-Cross: assembly is neither read by glslang nor written by SPIRV-Cross, and the
// position output is declared in it (`dcl_output_siv oN, position`), so the shift needs no
// value-flow analysis to find it (asm_shift.h). The output is the dump's own format.
#pragma once

#include "core/result.h"
#include "transpiler/d3dasm/asm_shift.h"
#include "transpiler/stereoshift.h"

namespace stereoshift {

// Its stage, from its shader-model line (nullopt: not assembly, or a model without a stage).
std::optional<Stage> assemblyStage(const SourceFile& input);

// The shift the options ask for, as the assembly printer renders it (and its check runs it): its
// cutoff; the rest of a ShiftSpec has no assembly spelling (asm_shift.h).
ShiftSpec assemblyShiftSpec(const TranspileOptions& options);

// What the assembly route writes: the converted text, or the input's as it is.
struct ConvertedAssembly {
  std::string text;
  bool copied = false;
};
// Converts `input`: fills `record` (its stage, the assembly facts, the route, the kind of output) and
// adds its warnings to `diags`; the located error (no file: the caller's) when the text or the
// options rule the conversion out. The driver takes it as the first of the routes for a stage with
// no SPIR-V module (stage_plan.h, writeWithoutModule).
Result<ConvertedAssembly> convertAssembly(const SourceFile& input, const TranspileOptions& options, StageRecord& record,
                                          Diagnostics& diags);

}  // namespace stereoshift
