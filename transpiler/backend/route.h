// The back end as a list of routes. Each route is one way of writing a converted stage (the input
// copied through, SPIR-V as it is, the HLSL or legacy GLSL source splice, SPIRV-Cross's re-emit);
// it says whether it takes a stage (and why not) and then emits it. The driver asks the routes in
// order (routes()) and runs the first that accepts; every text a route writes is re-compiled once,
// after it, by the driver, from the checks the route lists (EmitResult::checks).
#pragma once

#include "core/diagnostics.h"
#include "passes/pass.h"
#include "core/shader.h"
#include "transpiler/backend/back_end_options.h"
#include "transpiler/backend/emit_facts.h"

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace stereoshift {

// One more entry point of an HLSL file, converted on its own (its own front end and passes) so the
// vertex splice shifts it in the same text (HlslSpliceRoute). Listed by the driver before the passes.
struct OtherEntryPoint {
  std::string name;
  Stage stage = Stage::Unknown;
  std::string foundBy;
  // Converted (vertex entry points without -e): the conversion, or null when it failed (then
  // `diags` says why).
  const PassContext* context = nullptr;
  bool converted = false;   // its front end and passes ran
  bool ok = false;
  bool changed = false;
  Diagnostics diags;
};

// What a route is given: the stage after its passes.
struct EmitRequest {
  const SourceFile& input;
  const PassContext& context;  // module, eye parameters, classification, the run record
  const BackEndOptions& options;
  TargetLanguage target = TargetLanguage::Auto;  // resolved
  bool changed = false;                          // some pass changed the module
  std::vector<uint32_t> finalWords;              // the module after the passes, encoded
  std::string inheritedInvalid;                  // the front end's module already did not validate: why
  std::string entryPointOption;                  // -e NAME, when given
  std::vector<OtherEntryPoint>* otherEntries = nullptr;  // HLSL files: the file's other entry points
};

// One re-compile of emitted text, run by the driver after the route.
struct CompileCheck {
  std::string text;
  SourceLanguage language = SourceLanguage::Glsl;
  Stage stage = Stage::Unknown;
  std::string entryPoint = "main";
  bool vulkanSemantics = false;
  bool legacy = false;          // GLSL 1xx / ESSL 100 at `version`, AST only (verifyLegacyCompiles)
  // Through the front end, as the input was read (the analysis translation of 1xx included): for
  // dialects whose built-ins glslang declares only in that translation (compatibility-profile
  // geometry stages' gl_FrontColor, ...).
  bool throughFrontEnd = false;
  int version = 0;
  bool es = false;
  bool blankEffects = false;    // compile with effect-file technique / state blocks blanked
  std::string includeFrom;      // resolve #include from this file's directory
  std::string failure;          // the error when it does not compile
};

struct EmitResult {
  enum Status { Emitted, Declined, Failed } status = Failed;
  std::string output;
  bool binary = false;
  bool copied = false;                  // the output is the input's bytes
  std::vector<CompileCheck> checks;
  bool reportsVerified = false;         // the report says "verified" once the checks pass
  std::string declinedBecause;          // Declined: why (the next route takes the stage)
  // A check that fails declines (with the compiler's first error as the note) instead of failing
  // the stage: the next route, which carries everything, takes it.
  bool declineIfChecksFail = false;
};

// Whether a route takes a stage: Accept; Decline (the next route may, with `why` noted when it
// matters to the user); Refuse (an error: no route may write this stage).
struct RouteDecision {
  enum Kind { Accept, Decline, Refuse } kind = Decline;
  std::string why;
  bool noted = false;  // a Decline the user is told about (a note and the report's notes)
  static RouteDecision accept() { return {Accept, "", false}; }
  static RouteDecision decline(std::string why, bool noted = false) { return {Decline, std::move(why), noted}; }
  static RouteDecision refuse(std::string why) { return {Refuse, std::move(why), false}; }
};

class BackEndRoute {
 public:
  virtual ~BackEndRoute() = default;
  virtual const char* name() const = 0;
  // Whether the route writes the module (which must then validate) rather than the input's bytes.
  virtual bool needsValidModule() const { return true; }
  // Whether the route shifts the file's other entry points too (the driver converts them first).
  virtual bool needsOtherEntryPoints() const { return false; }
  // Whether a stage whose eye parameters are 3Dmigoto's StereoParams texture (--eye-source 3dmigoto)
  // may take the route: one that renders the texture's read, or one that changes nothing.
  virtual bool takesStereoParamsTexture() const { return false; }
  virtual RouteDecision accepts(const EmitRequest& request) const = 0;
  // Emits an accepted stage; facts go to `facts`, errors to `diags`.
  virtual EmitResult emit(const EmitRequest& request, EmitFacts& facts, Diagnostics& diags) const = 0;
};

// Resolves `Auto` to the input's own language.
TargetLanguage resolveTarget(const SourceInfo& info, const BackEndOptions& options);
// Whether the output is the input's own language and version (nothing to translate).
bool sameLanguageOutput(const SourceInfo& info, TargetLanguage target, const BackEndOptions& options);

// The edits the GLSL source splices (glsl_splice.h, the legacy route) render as text: the eye
// parameters, the shift and halo copies. Any other edit lives only in the IR (RunRecord::
// passesWithEditsBeyond names the passes that made one).
constexpr EditSet kGlslSpliceRenders = EditKind::EyeParameters | EditKind::PositionShift | EditKind::DerivedOutputShift;

// Which kinds of edit the output of a stage can carry, from the routes that can take it (every
// kind, unless the only route for it writes the stage's own text with some edits spliced in), and
// why not, for the passes' messages (PassOutput).
void decideOutputCapability(const SourceInfo& info, TargetLanguage target, PassOutput& output);

// The routes in the order the driver asks them: copy-through, SPIR-V binary, SPIR-V assembly, the
// HLSL source splice, the HLSL pixel-shader correction splice, the legacy GLSL source splice, the GLSL source splice, SPIRV-Cross's re-emit
// (which takes the rest).
const std::vector<std::unique_ptr<BackEndRoute>>& routes();

}  // namespace stereoshift
