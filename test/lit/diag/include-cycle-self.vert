// An #include of a file that includes itself (no guard) stops with the include chain at the
// directive that closes the cycle, instead of including forever (the timeout only guards the
// old behaviour: it never finished and grew its memory by tens of MB a second).
// RUN: %not timeout 300 %stereoshift %s -o %t.out 2>&1 | FileCheck %s
// RUN: test ! -e %t.out
// CHECK: {{.*}}Inputs/cycle/x.glsl:3:1: error: #include cycle: {{.*}}include-cycle-self.vert -> {{.*}}Inputs/cycle/x.glsl -> {{.*}}Inputs/cycle/x.glsl{{$}}
// CHECK-NEXT: #include "x.glsl"
// CHECK-NEXT: {{^[[:blank:]]*\^$}}
// CHECK-NEXT: {{^}}1 error generated.
#version 450
#extension GL_GOOGLE_include_directive : require
#include "Inputs/cycle/x.glsl"
void main() {
  gl_Position = vec4(helper(1.0));
}
