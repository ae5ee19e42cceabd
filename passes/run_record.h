// What one run of the pass pipeline did and found: each pass's status and its typed facts. The
// pass manager fills it (statuses) and the passes fill their facts; every layer above reads these
// fields (the back-end routes, the multi-entry HLSL splice, `verify`, the test fixture), and the
// JSON report is rendered from them by one function (transpiler/report.h). Nothing reads the report
// back: it is an output, not an interface between the parts of the tool.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace stereoshift {

enum class PassResult { Unchanged, Changed, Failed };
const char* toString(PassResult result);

// Why a shader gets (or does not get) the shift; reported per shader.
enum class Classification {
  Perspective,      // last pre-rasterization stage writing a clip position: shifted
  ConstantW1,       // every write of the position has the literal w = 1.0: 2D, nothing injected
  AlreadyStereo,    // already carries the eye parameters: never shifted twice
  Intermediate,     // pre-rasterization stage followed by a later one in its pipeline
  NoPositionStage,  // tessellation control, fragment, compute, task: no clip position to shift
  NoPositionOutput, // a pre-rasterization stage that writes no clip position
  NoVertexEmitted,  // a geometry shader that never emits a vertex: it rasterizes nothing, copied
};
const char* toString(Classification c);

// What a pass's change to the module is, in the terms a back-end route renders: a route that writes
// the original text plus edits takes a stage only when it can render every kind the passes made
// (routes never ask which pass ran). A pass declares its kinds beside its requirements (PassInfo);
// the manager records them on the pass's status when it changed the module.
enum class EditKind : uint32_t {
  EyeParameters = 1u << 0,        // eyeSign, separation, convergence declared where the shader reads them
  PositionShift = 1u << 1,        // the final clip position shifted at every return / emit
  DerivedOutputShift = 1u << 2,   // outputs computed from the clip position shifted like it (halo)
  PositionAtDepth = 1u << 3,      // a proven-2D position scaled to an eye depth
  SinglePassEye = 1u << 4,        // the eye taken from the view or instance index and handed on
  PerEyeCamera = 1u << 5,         // the per-eye camera position in view vectors
  UnprojectionCorrection = 1u << 6,  // a depth-reconstructed position corrected per eye
};
using EditSet = uint32_t;
constexpr EditSet kNoEdits = 0;
// The set of one kind.
constexpr EditSet editSet(EditKind kind) { return static_cast<EditSet>(kind); }
constexpr EditSet operator|(EditKind a, EditKind b) { return editSet(a) | editSet(b); }
constexpr EditSet operator|(EditSet a, EditKind b) { return a | editSet(b); }
constexpr EditSet kAllEdits = EditKind::EyeParameters | EditKind::PositionShift | EditKind::DerivedOutputShift |
                              EditKind::PositionAtDepth | EditKind::SinglePassEye | EditKind::PerEyeCamera |
                              EditKind::UnprojectionCorrection;
constexpr bool hasEdit(EditSet set, EditKind kind) { return (set & editSet(kind)) != 0; }
// "eye parameters, position shift": the kinds in `set`, for messages and tests.
std::string describeEdits(EditSet set);

// One pass that ran: its result, the kinds of edit it made (none unless it changed the module), and
// for a pass only pulled in by `--pass`, the named pass that required it.
struct PassStatus {
  std::string name;
  PassResult result = PassResult::Unchanged;
  std::string requiredBy;
  EditSet edits = kNoEdits;
};

// A construct whose value depends on the eye, as a per-eye pass found it: what it is and what was
// done with it (fixed, and how) or why it was left alone. Only the fields that apply are set.
struct ViewDependentUse {
  std::optional<std::string> construct, uniform, nameHint, use, reason, why, form, matrix, depth, depthRange, ndc,
      fix, projectionScale, reaches, eyeCentre;
  std::optional<int> count, loadsReplaced, line;
};

// clip-position-detection.
struct DetectionFacts {
  std::optional<Classification> classification;  // set when the pass ran
  std::vector<std::string> positions;  // the clip-position outputs, e.g. "gl_PerVertex.gl_Position"
  std::string alreadyStereo;           // why it is stereo already, when it is
  bool leftToDriver = false;           // perspective, not shifted: --corrections-only
};

// hud-at-depth.
struct HudAtDepthFacts {
  std::optional<size_t> stores;          // set when the element was placed at depth
  std::vector<std::string> placedAtDepth;
  std::string position, note;
  std::string leftAlone;                 // why it was not placed
};

// single-pass-stereo.
struct SinglePassFacts {
  std::string mode;                          // "multiview" / "instanced"; empty: not run
  std::optional<std::string> eyeVaryingName; // the `stereoEye` output it declared
  uint32_t eyeVaryingLocation = 0;
  std::optional<int> emitsRouted;            // geometry: EmitVertex sites that route the eye
  std::string eyeWrittenTo;                  // "layer" / "viewport"
  bool eyeHandedOn = false;
  std::string requiredExtension;             // an extension the output needs
  std::optional<int> instanceReadsRewritten;
};

// The eye parameters as declared (eye-params, or any pass that needed them: ensureEyeParams).
struct EyeParamFacts {
  std::string declared;  // "uniform block", "push constants", "loose uniforms", "specialization constants"
  std::optional<uint32_t> pushConstantOffset;
  std::string block, instance;            // uniform block
  std::optional<uint32_t> set, binding;
  std::map<std::string, std::string> renamed;  // wanted name -> the name chosen after a clash
  std::vector<uint32_t> specIds;
  std::vector<std::string> names;         // eyeSign, separation, convergence, ... as declared
};

// halo.
struct HaloFacts {
  std::optional<std::vector<std::string>> shiftedOutputs;  // set when the pass looked
  std::vector<std::string> derivedOutputs;  // computed from the position, not copies of it
  // The exact copies where the copy is the only store to its part of the output: the output (as
  // shiftedOutputs names it) and, as the source spells it, the part stored to (`vClip`, `surf.clip`,
  // `copies[1]`). A text splice re-copies the shifted position there.
  struct ExactCopy {
    std::string output, path;
  };
  std::vector<ExactCopy> exactCopies;
  // A derived output as a text splice can recompute it: written by one store, whose part the source
  // spells (`vScreenUV`), and whose computation reads the position only by loads of places the
  // source names (`gl_Position`, a local that holds it): those reads, through the shift, give the
  // shifted output.
  struct DerivedText {
    std::string output, path;
    std::vector<std::string> positionNames;
  };
  std::vector<DerivedText> derivedTexts;
  // Lanes of outputs the register copy shows computed from the position's x with a constant
  // coefficient (decompiled HLSL: `o3.xy = r0.xw + r0.zz;` after `r0.xz = float2(0.5,0.5) *
  // r1.xw;`, Unity's screen position), each moved by `coefficient` times the shift of x: the
  // output (as the source names it), the lane (0-3) and the coefficient. Not in shiftedOutputs (they
  // are no copies).
  struct MovedLane {
    std::string output;
    uint32_t lane = 0;
    float coefficient = 0.0f;
  };
  std::vector<MovedLane> movedLanes;
};

// stereo-shift.
struct ShiftFacts {
  std::optional<int> sites;  // returns / emits / stores shifted
  std::string form;          // "branch" / "select"
};

// per-eye-view.
// A per-eye camera as the shader's own text can carry it (a source splice): every read of the
// camera there becomes `camera + offset`, the offset written from these.
struct CameraText {
  std::string access;         // the camera as the source reads it: `viewPos`, `ubo.camPos`, `camPos` (anonymous block)
  uint32_t components = 3;    // vec3 or vec4 (a vec4's w is not moved)
  enum Offset { InverseViewProjection, InvertedClipMatrices, EyeOffsetParams } offset = EyeOffsetParams;
  std::vector<std::string> matrices;  // as the source reads them, in product order
  bool columnVectors = true;          // M * v (true) or v * M
  // The camera is the translation of `inverse(access)` (a view matrix inverted in the shader):
  // the text's `inverse(access)` is what moves, its column 3 by the offset.
  bool inverseOf = false;
  // The struct type of the access's first part when that is a plain struct (`CameraData` for
  // `camera.position`, `camera` a struct uniform or an anonymous block's struct member): a read of
  // that struct whole (`CameraData cam = camera;`) gives a copy whose camera is this eye's.
  std::string holderType;
};

struct PerEyeViewFacts {
  std::vector<ViewDependentUse> fixed, leftAlone;
  // One per fixed camera the text can name, in the order of `fixed`; `cameraTextMissing` says why
  // one cannot (an array element, the translation of an inverse view, a renamed built-in).
  std::vector<CameraText> cameraTexts;
  std::string cameraTextMissing;
  std::string skipped;
  std::string forcedCameraNotFound;
  std::set<std::string> perEyeOutputs;  // outputs that differ between the eyes by design
  std::string application;              // what the application must fill
};

// deferred-unprojection.
// A fix only the source text carries: an unprojection through a matrix in four cbuffer rows, as
// decompiled HLSL computes it (dp4 rows, mad chains over registers), placed by source line. q is
// made per eye by q -= column * s.x * (1 - s.y * q.w) (deferred_unprojection_pass.cpp) right after
// the statement that completes it.
struct RowProductTextFix {
  uint32_t afterLine = 0;  // the last line that writes a component of q (1-based, the main file)
  // Each component of q: the line of the statement that computes it and the lane of the
  // statement's value it is (`r1.xyzw = ...`: lanes 0-3 of one line; `r1.x = dot(...)`: lane 0).
  std::array<uint32_t, 4> lines{}, lanes{};
  // InvM's column of NDC x, element by element, as the source names it: "cb1[20].x", "-cb1[20].x".
  std::array<std::string, 4> column;
  // Which components the shader computes (w always; a compiler drops the lanes nothing reads).
  std::array<bool, 4> present{true, true, true, true};
  // The screen-to-world form: q = M * (ndc.x * z, ndc.y * z, z, 1) with z the view depth (the
  // depth the x and y terms are scaled by), corrected by q -= M[column of x] * s.x*(|z| - s.y)*sign(z);
  // the statement computing z and z's lane in its value.
  bool scaledByDepth = false;
  uint32_t depthLine = 0, depthLane = 0;
  // The pixel's x and y are the UV the depth is sampled at (no `* 2 - 1`): the matrix maps UV
  // space, its column of u twice InvM's column of NDC x, so `column` holds half of it.
  bool uvOfTheDepthTexture = false;
  // The pixel's x is a screen coordinate of unknown scale as the shader reads it (a pixel position,
  // a UV not the depth's, or what an input carries): the correction's column is `column` times the
  // coordinate's half-width h, which the matrix itself shows (docs/3dmigoto.md): its optical axis,
  // the coordinate where NDC x is 0, is at h from the coordinate's left edge (0 for a UV or a pixel
  // position), and at 0 for NDC (h = 1). `columnZ` and `translation` name InvM's column of the
  // depth and its constant column, i = 0..3, for that run-time computation. In the screen-to-world
  // form (scaledByDepth) M maps (c z, c' z, z, 1), its camera is M's constant column, and the axis
  // reads M's column of the depth alone.
  bool scaleFromTheMatrix = false;
  std::array<std::string, 4> columnZ, translation;
  // The screen-to-world map applied as a ray of basis vectors times the depth (basis_rays.cpp);
  // `columnY` names the basis of y, for the check that the depth is the view depth (the ray's part
  // along the view axis, orthogonal to the bases of x and y, is 1: not a ray to the far plane).
  bool basisRay = false;
  std::array<std::string, 4> columnY;
};

// A fix only the source text carries: a view-space x rebuilt from depth one component at a time,
// `x = ndc.x * depth * k` with k = 1/P00 a cbuffer element (or `/ P00`), as decompiled HLSL writes
// the view-ray form. Made per eye by x -= s.x * (|depth| - s.y) * |k| right after the statement
// that computes x (deferred_unprojection_pass.cpp, view rays).
struct ViewRayTextFix {
  uint32_t line = 0, lane = 0;            // the statement computing x, and x's lane in its value
  uint32_t depthLine = 0, depthLane = 0;  // the statement computing the depth factor
  std::string scale;                      // k as the source names it: "cb0[0].x", "(1 / cb2[6].x)"
};

// A fix only the source text carries: a view vector `v = c - p` from a camera position c (a cbuffer
// vector) to the position p = q.xyz / q.w a RowProductTextFix rebuilds, made this eye's by
// v += s.x * s.y * InvM[column of x].xyz where c is the camera InvM shows (its projection centre,
// InvM[column of z].xyz / InvM[3][z]); a light position (any other c) is left as it is. Checked at
// run time, since which constant is the camera is a value, not a name.
struct CameraTextFix {
  uint32_t line = 0;                   // the statement computing v (x, y and z on one line)
  std::array<uint32_t, 3> lanes{};     // the lanes of v.x, v.y, v.z in the statement's value
  std::array<std::string, 3> camera;   // c, element by element: "cb0[6].x"
  bool fromCamera = false;             // v = p - c (a view direction from the camera), not c - p
  std::array<std::string, 3> columnX;  // InvM[i][x], i = 0..2
  // The column whose xyz / w is the camera the matrix shows, i = 0..3: InvM[i][z] (the projection
  // centre), or a screen-to-world map's translation M[i][3] ("1" for the w of an affine map).
  std::array<std::string, 4> centre;
  // The matrix takes a screen coordinate of unknown scale (RowProductTextFix::scaleFromTheMatrix):
  // the offset is times the half-width the matrix shows, computed from these columns (i = 0..3;
  // `affine`: the screen-to-world form, which reads the depth's column alone).
  bool scaleFromTheMatrix = false, affine = false;
  std::array<std::string, 4> columnZ, translation;
};

// A fix only the source text carries: a re-projection `clip = VP * (p, 1)` over cbuffer rows of a
// point p computed from a position a RowProductTextFix corrects (SSAO's samples, a reflection's
// march), whose clip x is a coordinate of a read of the rebuild's depth texture: the corrected p is
// the true point, VP the mono matrix, and this eye's image has it at clip.x + a * s.x * (clip.w -
// s.y), with a = VP's row of x times InvM's column of NDC x (1 where VP is InvM's inverse, 0.5 for a
// matrix to UV space), computed where it runs. Right after the statement completing clip x and w.
struct ReprojectionTextFix {
  uint32_t afterLine = 0;
  // clip x (component 0) and w (component 1): the line of the statement computing each, its lane.
  std::array<uint32_t, 2> lines{}, lanes{};
  // VP's coefficients of p.x, p.y, p.z in clip x, and InvM's column of NDC x (the rebuild's
  // RowProductTextFix::column, i = 0..2), as the source names them.
  std::array<std::string, 3> rowX, column;
};

// A fix only the source text carries: a view-space position rebuilt from a ray the vertex stage
// interpolates, scaled to depth 1 by its own z and then by the view depth, p = ray * (far / ray.z) *
// depth01 (Unity's lights and screen-space shadows), where the ray is a full-screen pass's: its z is
// the far plane's (far / ray.z = 1; a light volume's is its surface's depth, and its vertices were
// shifted: another correction, none here). The pass is drawn at w = 1 and kept mono, so the ray at a
// pixel is the mono ray through that pixel, and p.x is off by s.x * (D - s.y) / P00 with D = |p.z|.
// 1/P00 is not in the pixel shader; the ray shows it: its x over z is k * (2 x / W - 1) at pixel x
// (W the width), linear across the screen, so k = x * ddx(ratio) - ratio, computed where it runs.
// p.x -= s.x * (|p.z| - s.y) * sign(p.z) * k after the statements completing p.x and p.z.
struct InterpolatedRayTextFix {
  uint32_t afterLine = 0;
  std::array<uint32_t, 2> lines{}, lanes{};  // p.x (0) and p.z (1): statement lines, lanes
  std::string rayX, rayZ;                    // the input's lanes, as the source names them: "v2.x"
  std::string farPlane;                      // the element the ray is scaled by over its z: "cb1[5].z"
};

// An unprojection `InvM * v` of source text as a splice can carry it: the product, found in the
// text as `<matrix> * <operand>` (GLSL) or `mul(<matrix>, <operand>)` (HLSL), goes through a helper that returns q' (deferred_unprojection
// _pass.cpp's rewrite).
struct UnprojectionText {
  std::string matrix;  // as the source reads it: `uInvViewProj`, `frame.invViewProj`
  bool hlslMul = false;  // HLSL's `mul(matrix, v)` (SPIR-V's v * M), not GLSL's `matrix * v`
  // A re-projection `P * vec4(p, 1)` of a corrected view-ray position back to this eye's screen
  // (its x + eyeSign*separation*(w - convergence)), not an unprojection.
  bool reprojection = false;
};

// A view ray's fix as GLSL text can carry it: the corrected value is what the shader assigns, once,
// to a local of its own (`vec3 viewPos = ray * depth;`), so the right-hand side of that assignment
// goes through a helper returning it with x - eyeSign*separation*(|z| - convergence) * (1/P00).
struct ViewRayText {
  std::string local;         // the local, as the text names it
  uint32_t components = 3;   // vec3 or vec4
  std::string inverseScale;  // 1/P00 as the text reads it (`frame.invProjection[0][0]`,
                             // `(1.0 / projection[0][0])`); empty: the injected eye parameter's
};

struct DeferredFacts {
  std::vector<ViewDependentUse> fixed, leftAlone;
  // Every rewrite of the module as source text carries it, or why not (an HLSL view ray or
  // re-projection, a matrix without a plain name, `v * M`): see UnprojectionText, ViewRayText.
  std::vector<UnprojectionText> unprojectionTexts;
  std::vector<ViewRayText> viewRayTexts;  // GLSL only
  std::string unprojectionTextMissing;
  std::vector<RowProductTextFix> textFixes;  // with PassOptions::sourceTextFixes
  std::vector<ViewRayTextFix> rayTextFixes;  // likewise
  std::vector<CameraTextFix> cameraTextFixes;  // likewise
  std::vector<ReprojectionTextFix> reprojectionTextFixes;  // likewise
  std::vector<InterpolatedRayTextFix> interpolatedRayTextFixes;  // likewise
  std::string leftAloneWhy;      // the whole shader left alone, and why
  std::string applicationFills;  // an injected parameter the application sets
};

struct RunRecord {
  std::vector<PassStatus> passes;  // in the order they ran
  DetectionFacts detection;
  HudAtDepthFacts hudAtDepth;
  SinglePassFacts singlePass;
  EyeParamFacts eyeParams;
  HaloFacts halo;
  ShiftFacts shift;
  PerEyeViewFacts perEyeView;
  DeferredFacts deferred;

  // The status of pass `name`, or null when it did not run.
  const PassStatus* status(const std::string& name) const;
  bool ran(const std::string& name) const { return status(name) != nullptr; }
  bool changed(const std::string& name) const;
  // The passes (by name, sorted, for the user's message) whose edits include a kind outside
  // `rendered`: what only the IR carries, which a route rendering `rendered` would lose.
  std::vector<std::string> passesWithEditsBeyond(EditSet rendered) const;
  // Whether some pass made an edit of this kind.
  bool madeEdit(EditKind kind) const;
};

}  // namespace stereoshift
