// The assembly shift: this turns the SM4/SM5 assembly of a vertex, domain or geometry shader (a
// 3Dmigoto `<hash>-vs.txt` dump) into its stereo version, as marked edits of its own text.
//
// SM4+ output registers cannot be read back, so the position output (`dcl_output_siv oN.xyzw,
// position`) is redirected: every instruction that writes oN writes a free temporary rP instead
// (`dcl_temps` raised by two: rP and a scratch rS), and before every return of the main program
// (vertex, domain) or every emit (geometry) a marked block reads 3Dmigoto's stereo parameters,
// writes rP to oN and then oN.x shifted:
//
//   ld_indexable(texture2d)(float,float,float,float) rS.xyzw, l(0, 0, 0, 0), t125.xyzw
//   add rS.w, rP.w, -rS.y            w - convergence
//   mad rS.w, rS.x, rS.w, rP.x       x + separation * (w - convergence)
//   ne  rS.x, rS.x, l(0.000000)      separation != 0 (mono keeps x bit for bit, -0 included)
//   add rS.y, rP.w, l(-1.000000)     the cutoff: |w - 1| > epsilon and w finite
//   lt  rS.y, l(epsilon), |rS.y|
//   and rS.x, rS.x, rS.y
//   lt  rS.y, |rP.w|, l(FLT_MAX)
//   and rS.x, rS.x, rS.y
//   movc rS.x, rS.x, rS.w, rP.x
//   mov oN.xyzw, rP.xyzw
//   mov oN.x, rS.x
//
// rP is never changed by the block, so a block before a conditional return (`retc_nz`) and the one
// before the final `ret` give the same result. 3Dmigoto's StereoParams texture at t125 gives the
// parameters (x: separation with the eye's sign, y: convergence); it is declared as
// `dcl_resource_texture2d (float,float,float,float) t125` unless the dump declares it already.
// SM4.x has no `ld_indexable`: the load is written `ld` there.
//
// Every edit is marked: inserted lines sit between `// ---- stereoshift: ... ----` and
// `// ---- end stereoshift ----`, and a changed line is kept above its new form as
// `// stereoshift was: <the line as written>`, so the original text can be recovered exactly.
//
// A pixel shader gets the corrections of what it rebuilds from depth instead (asm_unprojection.h):
// after the instruction that completes q = InvM * (ndc, depth, 1), a marked block reads StereoParams
// into a scratch temporary (`dcl_temps` raised by one) and corrects each component of q in place:
//
//   ld_indexable(texture2d)(float,float,float,float) rS.xyzw, l(0, 0, 0, 0), t125.xyzw
//   mad rS.w, -rS.y, qW, l(1.000000)      1 - convergence * q.w
//   mul rS.w, rS.w, rS.x                  d = separation * (1 - convergence * q.w)
//   mad qI, -cbN[col].c, rS.w, qI         q[i] -= InvM[i][x] * d, for each component
#pragma once

#include "core/shift_spec.h"
#include "transpiler/d3dasm/asm_halo.h"
#include "transpiler/d3dasm/asm_text.h"

#include <optional>
#include <string>
#include <vector>

namespace stereoshift::d3dasm {

struct AsmShiftResult {
  bool ok = false;
  AsmError error;               // !ok
  bool shifted = false;         // false: the stage has no position output (copied as it is)
  std::string whyUnchanged;     // !shifted: why
  bool alreadyStereo = false;   // !shifted because an instruction reads t125 (a stereo fix already)
  std::string output;
  std::string model;            // "vs_5_0"
  std::optional<Stage> stage;   // the model's stage
  size_t modelLine = 0;         // the line number of the shader-model line
  std::string positionRegister; // "o0"
  std::string positionTemp, scratchTemp;  // "r6", "r7"
  int redirectedWrites = 0;     // instructions that wrote the position
  int sites = 0;                // blocks written (returns or emits)
  std::vector<AsmMovedLane> movedLanes;  // output lanes moved with x (asm_halo.h)
  bool positionShifted = false; // false with moved lanes only (shiftPosition false)
  bool declaredStereoParams = false;  // t125 declared by the edit (false: the dump's own reused)
  // A pixel shader: the position rebuilds corrected (the output is `output` when any was).
  struct Correction {
    std::string form, matrix, depth, ndc, fix;
    size_t firstLine = 0, lastLine = 0;
  };
  std::vector<Correction> corrections;
  std::vector<std::string> leftAlone;  // a pixel shader: what was seen and left for a person, with why
};

// The assembly printer of the shift renders the spec's cutoff (core/shift_spec.h) with the eye's sign
// in 3Dmigoto's separation: branch-free (`movc`), the product and sum as one `mad`, whose fusing D3D
// leaves to the driver; the spec's form, fused, compensated and names have no assembly spelling.
// `pixelCorrections` false: a pixel shader is copied as it is (--no-deferred-unprojection).
// `shiftPosition` false (--corrections-only: the driver shifts the position): only the output lanes
// that move with x are written (the same block, the position written out unshifted); a stage
// without such lanes is copied.
AsmShiftResult shiftAssembly(const std::string& text, const ShiftSpec& spec, bool pixelCorrections = true,
                             bool shiftPosition = true);

// The original text of an output of shiftAssembly: the marked blocks dropped and each
// `// stereoshift was:` line restored (the check that the edits are all marked).
std::string undoAssemblyEdits(const std::string& text);

}  // namespace stereoshift::d3dasm
