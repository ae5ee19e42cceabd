#version 110
// Fixed-function lighting state cannot be translated: a located error, non-zero exit, no output.
// RUN: %not %stereoshift %s -o %t.out 2>&1 | FileCheck %s
// RUN: test ! -e %t.out
// CHECK: refuse-light-source.vert:11:21: error: 'gl_LightSource' is fixed-function state of the compatibility profile
// CHECK-NEXT: gl_FrontColor = gl_LightSource[0].diffuse * gl_Color;
// CHECK-NEXT: {{^[[:blank:]]*\^$}}
// CHECK-NEXT: {{^}}1 error generated.
void main() {
    gl_Position = ftransform();
    gl_FrontColor = gl_LightSource[0].diffuse * gl_Color;
}
