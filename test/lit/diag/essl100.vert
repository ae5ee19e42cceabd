#version 100
// ESSL 100 (attribute/varying) is refused with a clear error at 1:1 rather than a glslang failure.
// RUN: %not %stereoshift %s -o %t.out 2>&1 | FileCheck %s
// RUN: test ! -e %t.out
// CHECK: essl100.vert:1:1: error: ESSL 100 is not supported yet
// CHECK-NEXT: {{^}}1 error generated.
attribute vec3 aPosition;
uniform mat4 uMVP;
void main() {
  gl_Position = uMVP * vec4(aPosition, 1.0);
}
