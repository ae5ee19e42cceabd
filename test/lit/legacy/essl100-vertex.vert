#version 100
// A GL ES 2.0 SDK style vertex shader: the output stays ESSL 100 (attribute/varying, the original
// precision statement), verified at ESSL 100.
// RUN: %stereoshift %s -o %t.vert --report %t.json
// RUN: %rmchecks %t.vert | FileCheck %s
// RUN: FileCheck %s --check-prefix=REPORT --input-file %t.json
// RUN: glslangValidator -S vert %t.vert
// CHECK:      {{^}}#version 100
// CHECK:      {{^}}precision highp float;
// CHECK-NEXT: {{^}}attribute vec4 a_position;
// CHECK-NEXT: {{^}}varying vec4 v_color;
// CHECK:      {{^}}void main_stereoshift_mono()
// CHECK:      {{^}}uniform float eyeSign;
// CHECK-NOT:  isinf
// CHECK-NOT:  precise
// REPORT: "dialect": "100 es"
precision highp float;
attribute vec4 a_position;
varying vec4 v_color;
uniform mat4 u_mvpMatrix;
void main()
{
    v_color = a_position * 0.5 + 0.5;
    gl_Position = u_mvpMatrix * a_position;
}
