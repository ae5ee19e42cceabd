// HLSL source splice: stereo injection into HLSL text, for every HLSL shader that comes back as
// HLSL.
//
// The Debian SPIRV-Cross cannot re-emit HLSL geometry/hull/domain shaders, and what it re-emits of a
// vertex shader is no drop-in (its output struct `SPIRV_Cross_Output` moves SV_Position last, and
// D3D links stage outputs by register in declaration order; other entry points of the file are
// dropped). So the original HLSL text is kept and the clip-space shift is spliced into it:
//
//   vertex:   a cbuffer and a helper per shifted type (`T stereoshift_shift_T(T v)`) are inserted
//             before the first shifted entry point, and every `return e;` of each entry point
//             becomes `return stereoshift_shift_T(e);` (a float4 `: SV_Position` return value or a
//             struct with an SV_Position member); `out` parameters carrying SV_Position are shifted
//             before each return and at the end of the body. Structs, member order, semantics,
//             packoffsets, registers and attributes stay as written.
//   geometry: a cbuffer and a helper `T stereoshift_shift_T(T v)` (T = the stream element struct)
//             are inserted before the first function that appends to a stream, and every
//             `stream.Append(expr)` becomes `stream.Append(stereoshift_shift_T(expr))`.
//   domain:   the entry point is renamed `<entry>_stereoshift_mono` (its attributes are moved, left
//             behind as a comment), and a wrapper with the original attributes, return type,
//             parameter list and return semantic is appended after it; the wrapper calls the mono
//             function and shifts the SV_Position output (return value, struct member or `out`
//             parameter).
//
// The shift is the ShiftSpec's (passes/shift_emitter.h), the same description the SPIR-V route
// emits: `x' = x + (eyeSign * separation) * (w - convergence)` under its cutoff, as a branch or a
// select, plain, fused (`mad`) or compensated, `precise` or not. Everything outside the inserted
// text and the rewritten tokens is preserved byte for byte; inserted text starts on its own line
// and uses the file's line endings.
//
// The pieces (transpiler/backend/hlsl_splice/): the token view (the lexer's tokens, comments,
// strings and directives as the splice reads them), the top-level parser (functions, structs,
// attributes), the edit buffer (insertions by offset), the shift's text rendering and the geometry
// and domain rewriters. The splice understands comments, string literals, preprocessor lines (not
// macro expansion, except `#define`s whose body calls `.Append(`), balanced brackets and template
// argument lists; it is not a full HLSL parser.
#pragma once

#include "passes/run_record.h"
#include "core/shader.h"
#include "passes/shift_emitter.h"

#include <cstdint>
#include <string>
#include <vector>

namespace stereoshift {

// One vertex entry point to shift, with the outputs the passes found to be exact copies of its clip
// position (halo copies), named as the source names them: a member path of the returned struct
// (".clipCopy") or an `out` parameter ("clipCopy").
struct HlslSplicedEntry {
  std::string name;
  std::vector<std::string> copies;
  // Lanes of `out` parameters computed from the position's x (the halo pass's): before every
  // return, `o3.x += 0.5f * (stereoshift_shift_position(o0).x - o0.x);` (o0 the SV_Position out
  // parameter), with or without --corrections-only.
  std::vector<HaloFacts::MovedLane> movedLanes;
};

// Where the shift goes, and the shift itself (the ShiftSpec it extends: cutoff, epsilon, form,
// fused, compensated, precise and the eye parameter names).
struct HlslSpliceOptions : ShiftSpec {
  using Cutoff = CutoffMode;  // Epsilon: abs(p.w - 1.0f) > epsilon; Exact: p.w != 1.0f; None: always
  std::string entryPoint;  // e.g. "GSMain", "DSMain", "main"
  bool geometry = true;    // true: geometry shader; false: domain shader (tessellation evaluation)
  // Vertex shaders: every entry point of `vertexEntries` (or `entryPoint` alone when it is empty)
  // keeps its text and gets the shift at each of its returns; `geometry` is then ignored.
  bool vertex = false;
  std::vector<HlslSplicedEntry> vertexEntries;
  std::string cbufferName = "StereoParams";
  uint32_t cbufferRegister = 0;  // register(b<N>); an error if the source already uses b<N> in space0
  // --eye-source 3dmigoto: no cbuffer; 3Dmigoto's `Texture2D<float4> StereoParams : register(t125)`
  // (declared unless the file declares it: dumps carry it in their "3Dmigoto declarations") is read
  // once per shift helper, texel 0 into `stereoshift_stereo`, and the shift is
  // `x + stereoshift_stereo.x * (w - stereoshift_stereo.y)` (x is the separation with the eye's
  // sign, 0 in mono; y the convergence). The shift names are set by useStereoParamsTexture.
  bool stereoParamsTexture = false;
  bool declareStereoParams = true;  // set by the splice: false when the file declares StereoParams
  // --corrections-only (vertex shaders): the driver shifts the clip position itself; only the halo
  // copies of it (`vertexEntries[].copies`) are shifted, the position is returned as it is.
  bool correctionsOnly = false;
  // Vertex shaders: camera positions made this eye's (per-eye-view). Every read of `access` in a
  // function body becomes `<function>(access)`, the helper (`camera + offset`) defined in the
  // preamble, which then holds every eye parameter of `extraParams` too. `inverse`: the offset calls
  // `stereoshift_inverse(float4x4)` (HLSL has no inverse), defined there as well.
  struct CameraWrap {
    std::string access;    // `gEyePosW`
    std::string type;      // float3 or float4 (w not moved)
    std::string function;  // stereoshift_eye_<access>
    std::string offset;    // a float3 expression of the eye parameters and the shader's matrices
  };
  std::vector<CameraWrap> cameras;
  bool inverse = false;
  std::vector<std::string> extraParams;  // eye parameters after the three of the shift, in order
  // The epsilon is printed with 9 significant digits (round-trips a float); `precise` computes the
  // shifted x into a `precise float` temporary.
};

struct HlslSpliceResult {
  bool ok = false;
  std::string text;   // the stereo HLSL (ok == true)
  std::string error;  // what went wrong (ok == false)
  int line = 0;       // 1-based location of the problem; 0: no location (whole file)
  int column = 0;     // 1-based byte column; 0: unknown
  bool clash = false;  // the error is a clash with the source's names or registers (see SpliceError)
  int sites = 0;      // shifted outputs: Append calls (geometry), entry outputs (domain), returns (vertex)
};

HlslSpliceResult spliceHlslStereo(const std::string& source, const HlslSpliceOptions& options);

// Pixel shaders (3Dmigoto's StereoParams): the deferred pass's text fixes spliced in after the line
// that completes each rebuilt position or computes each view-space x (hlsl_splice/pixel.cpp), StereoParams declared before
// `entryPoint` unless the file declares it. An error (with its line) where the text does not
// show for certain where a component of the position lives.
HlslSpliceResult splicePixelCorrections(const std::string& source, const DeferredFacts& facts,
                                        const std::string& entryPoint);

// Pixel (and other unshifted) shaders with the deferred pass's unprojections: every
// `mul(<matrix>, <operand>)` the analysis fixed becomes `stereoshift_unproject_<matrix>(mul(...))`, the
// helper (q - M's column of NDC x * e*S*(1 - C*q.w), q when eyeSign is 0) and the eye parameters'
// cbuffer in a marked block before the first function that calls it (hlsl_splice/unprojections.cpp).
struct HlslUnprojectionOptions {
  std::string cbufferName = "StereoParams";
  uint32_t cbufferRegister = 0;
  std::string eyeSignName = "eyeSign", separationName = "separation", convergenceName = "convergence";
  struct Wrap {
    std::string matrix;    // `InvViewProj`
    std::string function;  // stereoshift_unproject_<matrix>
    int products = 1;      // the text must have exactly as many `mul(<matrix>, ...)`
  };
  std::vector<Wrap> wraps;
};
HlslSpliceResult spliceHlslUnprojections(const std::string& source, const HlslUnprojectionOptions& options);

// Sets `options` up for 3Dmigoto's StereoParams texture (see stereoParamsTexture).
void useStereoParamsTexture(HlslSpliceOptions& options);

// An entry point of an HLSL file, as its text shows it: named by a technique's
// `CompileShader(<profile>, Name(...))` (the profile gives the stage), or a function whose signature
// says its stage: a stream parameter (geometry), `[domain]` with `[outputcontrolpoints]` (hull),
// `[domain]` alone (domain), an output carrying SV_Position (vertex), SV_Target (pixel) or
// `[numthreads]` (compute).
struct HlslEntryPoint {
  std::string name;
  Stage stage = Stage::Unknown;
  std::string foundBy;  // "technique" or "signature"
};

// Every entry point of `source` in the order of their definitions (each name once); empty when the
// text does not scan.
std::vector<HlslEntryPoint> findHlslEntryPoints(const std::string& source);

}  // namespace stereoshift
