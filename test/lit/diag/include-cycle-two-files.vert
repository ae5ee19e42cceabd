// Two files that include each other (no guards): the cycle is named file by file.
// RUN: %not timeout 300 %stereoshift %s -o %t.out 2>&1 | FileCheck %s
// RUN: test ! -e %t.out
// CHECK: {{.*}}Inputs/cycle/q.glsl:2:1: error: #include cycle: {{.*}}include-cycle-two-files.vert -> {{.*}}Inputs/cycle/p.glsl -> {{.*}}Inputs/cycle/q.glsl -> {{.*}}Inputs/cycle/p.glsl{{$}}
// CHECK-NEXT: #include "p.glsl"
// CHECK-NEXT: {{^[[:blank:]]*\^$}}
// CHECK-NEXT: {{^}}1 error generated.
#version 450
#extension GL_GOOGLE_include_directive : require
#include "Inputs/cycle/p.glsl"
void main() {
  gl_Position = vec4(fromP(1.0));
}
