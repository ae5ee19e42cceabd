// A GLSL shader without #version: the error says what was assumed (GLSL 110) and why that
// fails, not glslang's "ES shaders for SPIR-V require version 310 or higher".
// RUN: %not %stereoshift %s -o %t.out 2>&1 | FileCheck %s
// RUN: test ! -e %t.out
// CHECK: version-missing.vert:1:1: error: no #version directive: GLSL without one is version 110, which stereoshift cannot convert
// CHECK-NOT: ES shaders
void main() {
  gl_Position = vec4(0.0);
}
