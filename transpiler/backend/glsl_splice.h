// GLSL source splice: this turns a GLSL / ESSL vertex, tessellation-evaluation or geometry shader
// of any version into its stereo version in the same dialect, drop-in (and a stage that gets no
// shift, a fragment shader say, into its per-eye version where the passes fixed a camera or an
// unprojection): the original text with a
// few marked edits. The passes decided what to change (for ESSL 100 / GLSL 1xx on the analysis
// translation, transpiler/frontend/legacy_glsl.h); their decisions are rendered into the user's own
// text, so every declaration, layout, qualifier, struct or block varying, #version line, #extension,
// comment, #include, #ifdef branch and macro stays as written:
//
//   - vertex and tessellation-evaluation shaders: every token `main` (outside comments) becomes
//     `main_stereoshift_mono`, and a new `main` appended at the end of the file calls it, then
//     shifts gl_Position under the cutoff, then gives the outputs that are exact copies of the clip
//     position (halo) the shifted value; an output computed from the position reads it, in its one
//     assignment, through `stereoshift_shifted_position()`;
//   - geometry shaders: every statement `EmitVertex();` / `EmitStreamVertex(n);` becomes
//     `{ stereoshift_shiftPosition(); EmitVertex(); }` (the shift of the vertex about to be
//     emitted), with a prototype of the helper before each function that emits and its definition
//     appended at the end of the file;
//   - per-eye cameras (per-eye-view): every read of the camera in a function body becomes
//     `stereoshift_eye_<camera>(camera)`, with the helper's prototype before each function that
//     reads it and its definition (`camera + this eye's offset`) in the appended block;
//   - unprojections (deferred-unprojection, any stage): every `InvM * v` the analysis fixed becomes
//     `stereoshift_unproject_<InvM>(InvM * v)`, likewise with a prototype and a definition; a
//     re-projection of a corrected position `P * v`, `stereoshift_reproject_<P>(P * v)`; a view
//     ray's position `p = ray * depth;`, `p = stereoshift_view_ray_<p>(ray * depth);`;
//   - appended with it: the eye parameters, as the passes declared them (`declarations`: a uniform
//     block with its layout, or loose uniforms when none are given); or, where they join the
//     shader's own push-constant block, inserted in that block before its closing brace.
//
// Every edit outside the appended block is one of those renames or wraps; the appended block and
// each prototype sit between the marker comments "---- stereoshift" and "---- end stereoshift".
//
// The shift is the ShiftSpec's (passes/shift_emitter.h): `x + (eyeSign*separation)*(w - convergence)`
// under `eyeSign != 0 && |w - 1| > epsilon && w finite` (or `w != 1`, or no cutoff), as a branch or a
// select. GLSL 1xx has neither `precise` nor `fma` nor (below 130) `isinf`: the plain form is used
// and "finite" is `abs(w) <= 3.40282347e+38` (false for inf and NaN, as `!isinf(w)` with the other
// terms is). From GLSL 400 / ESSL 320 on, the shift is a `precise` temporary when the spec asks
// for NoContraction, and `fma` when it asks for the fused form. Every byte of the original stays
// where it was.
#pragma once

#include "core/diagnostics.h"
#include "core/shader.h"
#include "passes/shift_emitter.h"

#include <string>
#include <vector>

namespace stereoshift {

struct GlslSpliceOptions : ShiftSpec {
  int version = 100;
  bool es = true;
  Stage stage = Stage::Vertex;  // Vertex, TessEvaluation or Geometry
  // The entry function (-e for GLSL; `main` by default): renamed `<entry>_stereoshift_mono`, and a
  // shifting `<entry>` appended, so the build that names it compiles the output unchanged.
  std::string entryPoint = "main";
  // The eye parameters' declaration, one line each; empty: `uniform float <name>;` for the three
  // names of the spec (loose uniforms). With a block, the spec's names are its members as the shift
  // reads them (`stereo.eyeSign`).
  std::vector<std::string> declarations;
  // Extensions the edits need (`GL_EXT_multiview` for gl_ViewIndex), each `#extension NAME : require`
  // in a marked block right after the #version line.
  std::vector<std::string> extensions;
  // The shader's own push-constant block takes the eye parameters (--eye-source push-constant on a
  // shader that has one): these member declarations go in one marked insertion before its closing
  // brace, and nothing is declared in the appended block.
  std::vector<std::string> pushConstantMembers;
  // Outputs (as written in the source) that are exact copies of gl_Position: given the shifted value.
  std::vector<std::string> haloCopies;
  // Outputs computed from the position (halo: `vScreenUV = gl_Position.xy / gl_Position.w ...`):
  // in the one assignment of `output`, every read of one of `positionNames` (gl_Position, a local
  // holding it) becomes `stereoshift_shifted_position(name)`, the position as the shift leaves it.
  struct DerivedHalo {
    std::string output;
    std::vector<std::string> positionNames;
  };
  std::vector<DerivedHalo> derivedHalos;
  // Camera positions made this eye's (per-eye-view): every read of `access` in a function body
  // becomes `<function>(access)`, the function's prototype goes before each function that reads it
  // and its definition, `camera + offset`, into the appended block.
  struct CameraWrap {
    std::string access;    // `viewPos`, `ubo.camPos`
    std::string type;      // vec3 or vec4 (w not moved)
    std::string function;  // stereoshift_eye_<access, `.` as `_`>
    std::string offset;    // a vec3 expression of the eye parameters and the shader's own matrices
    // `inverse(access)` is wrapped instead (a camera taken from an inverted view matrix): the helper
    // takes and returns the mat4 and moves its column 3.
    bool inverseOf = false;
    // The struct type of the access's first part (`CameraData` for `camera.position`): a read of that
    // part whole becomes `stereoshift_holder_<part>(part)`, a copy whose camera is this eye's.
    std::string holderType;
  };
  std::vector<CameraWrap> cameras;
  // Unprojections made this eye's (deferred-unprojection): every `<matrix> * <operand>` in a function
  // body becomes `<function>(<matrix> * <operand>)`, the helper returning
  // q - matrix[0] * (eyeSign*separation)*(1 - convergence*q.w) (q itself when eyeSign is 0).
  struct UnprojectionWrap {
    std::string matrix;    // `uInvViewProj`, `frame.invViewProj`
    std::string function;  // stereoshift_unproject_<matrix, `.` as `_`>
    int products = 1;      // how many products through it the analysis fixed: the text must have as many
    // A re-projection of a corrected view-space position (stereoshift_reproject_<matrix>): the
    // helper returns q with x + (eyeSign*separation)*(q.w - convergence), back to this eye's screen.
    bool reprojection = false;
  };
  std::vector<UnprojectionWrap> unprojections;
  // View rays made this eye's (deferred-unprojection): the right-hand side of the one assignment
  // `<local> = <expression>` becomes `<function>(<expression>)`, the helper returning p with
  // x - (eyeSign*separation)*(abs(p.z) - convergence)*inverseScale (p itself when eyeSign is 0).
  struct ViewRayWrap {
    std::string local;         // `viewPos`
    std::string type;          // vec3 or vec4
    std::string function;      // stereoshift_view_ray_<local>
    std::string inverseScale;  // 1/P00 as a GLSL expression
  };
  std::vector<ViewRayWrap> viewRays;
  // false: the stage gets no shift (a fragment shader, a stage before the one that rasterises): no
  // `main` renamed, the appended block holds the eye parameters and the helpers only.
  bool shift = true;
};

struct GlslSpliceResult {
  bool ok = false;
  std::string text;
  std::string error;
  int line = 0, column = 0;  // where the problem is; 0: whole file
  int sites = 0;             // places that shift: 1 for a wrapped main, one per emit of a geometry shader
};

// A GLSL float literal that reads back as `value` (9 significant digits, always with a `.` or an
// exponent): the one spelling every GLSL text the splices and the text-only shift write uses.
std::string glslFloatLiteral(float value);

// Whether GLSL `version` (ESSL when `es`) has `precise` and `fma` (GLSL 400, ESSL 320).
bool glslHasPreciseAndFma(int version, bool es);

GlslSpliceResult spliceGlslStereo(const std::string& source, const GlslSpliceOptions& options);

// The outputs of `source` whose every assignment is `name = gl_Position;` (exact copies).
std::vector<std::string> exactPositionCopies(const std::string& source);

}  // namespace stereoshift
