// A GL shader that declares its own `separation` uniform keeps it; the injected loose uniform is
// renamed (with a warning), the shift uses the renamed one, and the result compiles.
// RUN: %stereoshift --verify %s -o %t.out.vert --report %t.json 2>&1 | FileCheck %s --check-prefix=WARN
// RUN: %rmchecks %t.out.vert | FileCheck %s
// RUN: FileCheck %s --check-prefix=REPORT --input-file %t.json
// RUN: glslangValidator %t.out.vert
// WARN: name-clash-gl330.vert: warning: the shader already declares 'separation'; the injected one is named 'separation_stereo'
#version 330
uniform mat4 uMVP;
uniform float separation;
in vec3 aPosition;
// CHECK-DAG: {{^}}uniform float separation;
// CHECK-DAG: {{^}}uniform float separation_stereo;
// CHECK-DAG: {{^}}uniform float eyeSign;
// CHECK-DAG: {{^}}uniform float convergence;
void main() {
  gl_Position = uMVP * vec4(aPosition * separation, 1.0);
// CHECK: void main()
// CHECK: aPosition * separation;
// CHECK: if (({{[A-Za-z_.]*}}eyeSign != 0.0{{f?}}) && ((abs(gl_Position.w - 1.0) >
// CHECK: float {{_[0-9]+}} = eyeSign * separation_stereo;
// CHECK: gl_Position.x =
}
// REPORT: "renamed": {
// REPORT-NEXT: "separation": "separation_stereo"
// REPORT-NEXT: },
