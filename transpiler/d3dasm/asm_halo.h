// The halos of vertex- and domain-shader assembly: this turns the outputs of a 3Dmigoto `-vs.txt`
// / `-ds.txt` dump into the lanes that must move with the position's x, so that what the pixel
// shader reads there matches the shifted image: an exact copy of x (Unreal's `ScreenPosition =
// Position`, `mov o1.xyzw, r0.xyzw` beside `mov o0.xyzw, r0.xyzw`) and a lane that is x times a
// constant plus terms that do not depend on x (Unity's screen position for soft particles, water,
// refraction: `mul r0.xz, r1.xxwx, l(0.5, 0, 0.5, 0)` then `add o1.xy, r0.zzzz, r0.xwxx`).
//
// How: the evaluation of asm_evaluation.h (every lane a sum of terms with constant-buffer or
// constant coefficients) gives each output lane's value at each return. A lane L moves by `a`
// times the shift of x when, x's value being F = sum of its parts, L has every part of F scaled
// by one constant a (each key: the term with its coefficient's element), and what is left of L
// has no term that may depend on x's value (asm_evaluation.h's mayDependOn, which counts a value
// it lost track of as depending). The same value as x is a copy (a = 1, moved bit for bit with
// x). A lane taken at one return and not at another, or with another a, is not taken: the text
// gets one block per return, and a lane that moves at one of them only would need the branch.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace stereoshift::d3dasm {

class Program;  // asm_interpreter.h

struct AsmMovedLane {
  uint32_t reg = 0, lane = 0;  // o<reg>.<lane>
  float coefficient = 1.0f;    // the lane moves by coefficient * (shifted x - x)
  bool copy = false;           // the position's x itself: takes the shifted x bit for bit
  size_t line = 0;             // the line of the instruction that computed the lane's value
};

// The lanes of `program` (decoded with DecodeFor::Analysis) that move with the position's x, by
// output register and lane; none when it has no position output, writes an output through an
// index, or has no return.
std::vector<AsmMovedLane> findAsmMovedLanes(const Program& program);

}  // namespace stereoshift::d3dasm
