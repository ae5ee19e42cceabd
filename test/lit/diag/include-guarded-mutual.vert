// Files that include each other behind include guards (or #pragma once) are no cycle: the inner
// copy adds nothing, so the shader converts.
// RUN: %stereoshift %s -o %t.out
// RUN: test -e %t.out
#version 450
#extension GL_GOOGLE_include_directive : require
#include "Inputs/cycle/guarded-a.glsl"
#include "Inputs/cycle/once.glsl"
void main() {
  gl_Position = vec4(fromA(1.0) + fromB(1.0) + fromOnce(1.0));
}
