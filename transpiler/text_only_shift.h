// The text-only shift: this turns a GLSL vertex, tessellation-evaluation or geometry shader that
// glslang cannot parse (a construct it does not know at the source's version, or a crash inside it)
// into its stereo version from the text alone, with the GLSL splice (glsl_splice.h): `main`
// renamed and a shifting `main` appended, or every EmitVertex wrapped. No analysis ran, so what
// needs one is not done: no halo copies, no per-eye camera, no deferred unprojection, no re-compile,
// and the proof that a shader is 2D only where its text shows it (every write of gl_Position with
// the literal w = 1, in every unit of the stage: copied unchanged, as the analysis copies a 2D
// stage; elsewhere the runtime cutoff still keeps w = 1 draws mono). The driver
// takes it only when the front end failed, warns, and records it (`"analysis": "text-only"`);
// --require-analysis makes the front end's failure an error again.
//
// It never guesses: the text must lex cleanly (no open comment or string, brackets balanced), have
// a #version the splice reads, write gl_Position in its own text (and, in a geometry shader, call
// EmitVertex / EmitStreamVertex as statements), and not declare the eye parameters already.
// The eye parameters are loose uniforms for OpenGL GLSL, and for Vulkan GLSL (told from the text:
// descriptor sets, push constants, Vulkan built-ins) a uniform block in set 0 after the highest
// binding the text names, unless the options ask for another source, set or binding.
#pragma once

#include "core/diagnostics.h"
#include "passes/pass_options.h"
#include "passes/run_record.h"
#include "core/result.h"
#include "core/shader.h"
#include "transpiler/backend/back_end_options.h"
#include "transpiler/transpile_options.h"

#include <optional>
#include <string>
#include <vector>

namespace stereoshift {

// A stage with the shift spliced from its text alone; the shifts below return it, or why the text
// alone is not enough (core/result.h).
struct TextOnlyShift {
  std::string output;
  int sites = 0;
  std::string eyeParams;             // "loose uniforms", "uniform block", ...
  std::vector<std::string> notDone;  // what an analysis would have done
  // Nothing spliced, `output` the input unchanged, for what the text shows: ConstantW1, every write
  // of gl_Position in the stage's text has the literal w = 1 (textKeepsUnitW); NoVertexEmitted, a
  // geometry stage none of whose units emits a vertex; NoPositionOutput, a stage of several units
  // none of which names gl_Position.
  std::optional<Classification> copiedAs;
};

// What in `text` glslang may read more narrowly than drivers do: an #extension it enables (glslang
// lacks some extensions' built-ins at some versions), a line continuation, the compatibility
// profile; "" when none. The text-only shift is for those, never for a shader that is simply wrong.
std::string glslangGapIn(const std::string& text);

// What a text-only shift does not do, that an analysis would have done (the report's `not_done`).
const std::vector<std::string>& textOnlyNotDone();

// Whether the driver may try the text-only shift for a stage of `language` the front end could not
// parse: a pre-rasterization stage, kept in its own language, two-pass stereo, no --require-analysis.
bool mayShiftFromText(Stage stage, SourceLanguage language, const PassOptions& passes, const BackEndOptions& backEnd);

// `units`: what the stage's other compilation units say by their text (OpenGL links a stage from
// several; transpile_options.h, StageUnits): a text that writes no gl_Position itself still takes
// the shift around its `main` where another unit writes it; the 2D proof covers every unit; a
// geometry stage none of whose units emits, or a stage none of whose units names gl_Position, is
// copied (TextOnlyShift::copiedAs).
Result<TextOnlyShift> shiftFromText(const SourceFile& input, Stage stage, const PassOptions& options,
                                    const StageUnits& units = {});

// Whether GLSL text calls EmitVertex or EmitStreamVertex.
bool textCallsEmit(const std::string& text);

// Whether GLSL text assigns gl_Position (or a component of it) itself.
bool textWritesPosition(const std::string& text);

// Whether every function GLSL text declares at its top level without a body (a prototype) has its
// body in the text too: a unit that calls no function of another unit (GLSL needs a prototype for one).
bool textDefinesEveryPrototype(const std::string& text);

// Whether GLSL text names gl_Position anywhere (code or macro).
bool textNamesPosition(const std::string& text);

// The text's 2D proof: whether every write of gl_Position in GLSL text leaves its w the literal 1
// (`gl_Position = vec4(..., 1.0);`, `gl_Position.w = 1.0;`) or untouched (lanes without w); a
// compound assignment, another right-hand side, an index, the position handed to a function or
// named in a macro is no proof. True for a text that writes none (no other unit's proof broken).
bool textKeepsUnitW(const std::string& text);

// Whether GLSL text says it is Vulkan GLSL (descriptor sets, push constants, Vulkan built-ins, subpass
// inputs, GL_KHR_vulkan_glsl): OpenGL's compilers cannot judge it.
bool isVulkanGlslText(const std::string& text);

// HLSL (hlsl_text_only_shift.cpp): for text a decompiler wrote from a compiled shader (a 3Dmigoto
// dump by its name or its header), which the D3D compiler accepted, so that glslang's refusal or
// crash is glslang's gap. The HLSL splice alone: the entry point by its signature, the SV_Position
// output from the text, the eye parameters a cbuffer at the first free b register (or
// --hlsl-register), or 3Dmigoto's StereoParams texture with --eye-source 3dmigoto.
bool isDecompiledHlsl(const SourceFile& input);
// An error of decompiled text's own, which no D3D compiler would have taken either (the decompiler
// or a hand edit broke it): an `#error` outside every #if group, a bracket, brace or parenthesis
// without its partner, a comment or string left open. The text-only shift is never taken past one.
std::optional<Diagnostic> ownTextError(const SourceFile& input);
Result<TextOnlyShift> shiftHlslFromText(const SourceFile& input, Stage stage, const TranspileOptions& options);

}  // namespace stereoshift
