// A GL shader that declares its own `separation` uniform keeps it; the injected loose uniform is
// renamed (with a warning), the shift uses the renamed one, and the result compiles.
// RUN: %stereoshift --verify %s -o %t.out.vert --report %t.json 2>&1 | FileCheck %s --check-prefix=WARN
// RUN: %rmchecks %t.out.vert | FileCheck %s
// RUN: FileCheck %s --check-prefix=REPORT --input-file %t.json
// RUN: glslangValidator %t.out.vert
// CHECK: {{^}}uniform float separation;
// CHECK: gl_Position = uMVP * vec4(aPosition * separation, 1.0);
// CHECK: {{^}}uniform float eyeSign;
// CHECK-NEXT: {{^}}uniform float separation_stereo;
// CHECK-NEXT: {{^}}uniform float convergence;
// CHECK: if (eyeSign != 0.0 && abs(gl_Position.w - 1.0) >
// CHECK: gl_Position.x = gl_Position.x + (eyeSign * separation_stereo) * (gl_Position.w - convergence);
// WARN: name-clash-gl330.vert: warning: the shader already declares 'separation'; the injected one is named 'separation_stereo'
#version 330
uniform mat4 uMVP;
uniform float separation;
in vec3 aPosition;
void main() {
  gl_Position = uMVP * vec4(aPosition * separation, 1.0);
}
// REPORT: "renamed": {
// REPORT-NEXT: "separation": "separation_stereo"
// REPORT-NEXT: },
