#version 100
// Redefining a built-in ESSL 1.00 has (cross) is an error in ESSL 1.00 as in ESSL 3 (Mesa refuses it
// too): the error stays, at the definition, and nothing is written.
// RUN: not %stereoshift %s -o %t.vert 2>&1 | FileCheck %s
// RUN: not test -e %t.vert
// CHECK: essl100-redefined-builtin.vert:[[@LINE+3]]:{{[0-9]+}}: error: {{.*}}redefinition of built-in function
attribute vec4 aPos;
uniform mat4 uMVP;
vec3 cross(vec3 a, vec3 b) { return a; }
varying vec3 vN;
void main() { vN = cross(aPos.xyz, vec3(0.0, 1.0, 0.0)); gl_Position = uMVP * aPos; }
