#version 3x0
// A garbled #version is named as such, not reported as glslang's fallback to ESSL 100 ("ES
// shaders for SPIR-V require version 310 or higher").
// RUN: %not %stereoshift %s -o %t.out 2>&1 | FileCheck %s
// RUN: test ! -e %t.out
// CHECK: version-garbled.vert:1:1: error: '#version 3x0': not a GLSL version
// CHECK-NEXT: #version 3x0
// CHECK-NEXT: {{^[[:blank:]]*\^$}}
// CHECK-NEXT: {{^}}1 error generated.
// CHECK-NOT: ES shaders
void main() {
  gl_Position = vec4(0.0);
}
