// The position rebuild of pixel-shader assembly: this turns a deferred-lighting (or SSAO, fog,
// decal) pixel shader's `q = InvM * (ndc.x, ndc.y, depth, 1)` over four constant-buffer rows, as the
// D3D compiler writes it in assembly, into a found unprojection: the registers that hold q's
// components after the instruction that completes it, and InvM's column of NDC x, for the
// correction the assembly route writes there (asm_shift.h):
//     q -= InvM[column of x] * s.x * (1 - s.y * q.w)
// (s: 3Dmigoto's StereoParams texel 0; the maths in docs/3dmigoto.md, "Pixel-shader corrections").
//
// How it is found: each register component an instruction writes is a value of its own (the
// compiler reuses r0..rN for many values), evaluated in program order as a sum of terms, each with a
// coefficient that is one constant-buffer element times a constant, or a constant. `mul`/`mad`/
// `add`/`dp2`-`dp4`/`mov` and the `-` modifier are looked through; a product of a value with a
// constant-buffer element makes that value a term (the pixel's NDC x, however it was computed, is
// one term); anything else (a texture read, `rcp`, `movc`, an instruction the interpreter does not
// run) is a new term. Every value remembers what it was computed from: input lanes and textures.
// A component of q is then a value with exactly three terms and one constant-buffer element as its
// constant part, the elements of one matrix in either storage:
//   columns (`mad r1.xyzw, r0.xxxx, cb1[20].xyzw, r1.xyzw`): component i reads lane i of each column;
//   rows (`dp4 r2.x, r1.xyzw, cb2[32].xyzw`): component i is row k+i.
// and the terms are the pixel's x (lane 0 of an input, SV_Position or an interpolated coordinate, no
// texel), its y (lane 1 of the same input) and a depth (read from a texture); or, in the
// screen-to-world form, the pixel's x and y each multiplied by that depth term (a product of two
// values is a term that remembers its factors). A shadow or texture
// matrix applied to interpolated positions has no texel in it and is not one. Control flow: values
// written in one branch of an `if` are new terms after its `endif`, a branch that returns does not
// reach it, and what a loop writes is unknown in and after it.
#pragma once

#include "transpiler/d3dasm/asm_interpreter.h"

#include <array>
#include <string>
#include <vector>

namespace stereoshift::d3dasm {

struct AsmUnprojection {
  size_t afterLine = 0;                 // index in AsmText::lines of the instruction completing q
  size_t firstLineNumber = 0, lastLineNumber = 0;  // the instructions that compute q's components
  std::array<std::string, 4> q;         // where each component of q is there: "r2.x"
  std::array<std::string, 4> column;    // InvM's column of NDC x, one element each: "cb1[20].x"
  std::array<float, 4> columnScale{1, 1, 1, 1};  // the constant each element is multiplied by
  std::string rows;                     // "cb1[20], cb1[21], cb1[22], cb1[23]"
  std::string storage;                  // "columns (mad)" or "rows (dp4)"
  std::string depth;                    // the texture the depth is read from: "t0"
  std::string ndc;                      // the input the pixel's x and y come from: "v0"
  // The pixel's x and y are the UV the depth is sampled at (no `* 2 - 1`): the matrix maps UV
  // space, and columnScale holds half of its column of u.
  bool uvOfTheDepthTexture = false;
  // The pixel's x is a screen coordinate of unknown scale (a pixel position, a UV not the depth's):
  // the correction's column is InvM's times the coordinate's half-width, computed where it runs from
  // the matrix's optical axis (as the decompiled route's RowProductTextFix::scaleFromTheMatrix).
  // `columnZ` and `translation` are the operands of InvM's column of the depth and of its constant
  // column, i = 0..3, with their signs ("-cb1[22].x"); every element the computation reads has a
  // scale of 1 or -1.
  bool scaleFromTheMatrix = false;
  std::array<std::string, 4> columnZ, translation;
  // The screen-to-world form, q = M * (ndc.x * z, ndc.y * z, z, 1): corrected by
  // q -= M[column of x] * s.x * (|z| - s.y) * sign(z), z read from `depthRegister` ("r1.x").
  bool scaledByDepth = false;
  std::string depthRegister;
  // A view vector v = c - p from a camera position c (one constant-buffer vector) to the rebuilt
  // position p = q.xyz / q.w, x, y and z written by one instruction: made this eye's by
  // v += s.x * s.y * InvM[column of x].xyz where c is the camera InvM shows (its projection centre
  // InvM[column of z].xyz / InvM[3][z], checked at run time; a light's position is left alone).
  struct Camera {
    size_t afterLine = 0, lineNumber = 0;
    std::array<std::string, 3> v, camera;  // "r0.x"; "cb1[24].x"
    std::array<std::string, 4> centre;    // InvM[i][z]
    bool fromCamera = false;              // v = q.xyz / q.w - c, not c - q.xyz / q.w
  };
  std::vector<Camera> cameras;
};

// The view-ray form spelled per component: a view-space x = ndc.x * depth * k with k one
// constant-buffer element (1/P00) or divided by one (`div r2.x, r1.x, cb0[6].x`), and its y made
// the same way from the same depth. Corrected right after the instruction computing x:
//     x -= s.x * (|depth| - s.y) * |k|
struct AsmViewRay {
  size_t afterLine = 0;          // index in AsmText::lines of the instruction computing x
  size_t lineNumber = 0;
  std::string x;                 // where x is: "r2.x"
  std::string depthRegister;     // where the depth factor is: "r1.x"
  std::string element;           // k's element: "cb0[0].x"
  bool divides = false;          // k = scale / element
  float scale = 1.0f;
  std::string depth, ndc;        // the depth's texture, the NDC's input
};

struct AsmUnprojections {
  std::vector<AsmUnprojection> found;
  std::vector<AsmViewRay> rays;
  // Rebuilds found but not corrected, each with the line and why (left for a person).
  std::vector<std::string> leftAlone;
};

// Every such unprojection of `program` (decoded with DecodeFor::Analysis from `text`), in program
// order; none when q's components are not all where the text can correct them right after the
// instruction completing q (a component overwritten before it, or computed in another block). A
// rebuild whose pixel x is a screen input as it is, or times one constant or element (a UV, a pixel
// position: the matrix may map UV space, whose column is twice the correction's), is left alone.
AsmUnprojections findAsmUnprojections(const AsmText& text, const Program& program);

}  // namespace stereoshift::d3dasm
