#version 300 es
// An ESSL 300 shader (which glslang 12 only turns into SPIR-V at 310) comes back as ESSL 300 with
// its loose uniforms, the eye parameters as loose uniforms, and no default-block wrapper struct.
// ESSL requires #version on line 1, so the RUN lines follow it.
// RUN: %stereoshift --verify %s -o %t.out.vert
// RUN: %rmchecks %t.out.vert | FileCheck %s
// RUN: glslangValidator %t.out.vert
// CHECK: {{^}}#version 300 es{{$}}
precision highp float;
uniform mat4 uMVP;
// CHECK-NOT: gl_DefaultUniformBlock
// CHECK-NOT: #extension
// CHECK-DAG: {{^}}uniform {{(highp )?}}mat4 uMVP;
in vec3 aPosition;
in vec2 aUV;
out vec2 vUV;
// CHECK-DAG: {{^}}in {{(highp )?}}vec3 aPosition;
// CHECK-DAG: {{^}}in {{(highp )?}}vec2 aUV;
// CHECK-DAG: {{^}}out {{(highp )?}}vec2 vUV;
void main() {
  vUV = aUV;
  gl_Position = uMVP * vec4(aPosition, 1.0);
// CHECK: void main_stereoshift_mono()
// CHECK: vUV = aUV;
// CHECK: gl_Position = uMVP * vec4(aPosition, 1.0);
// CHECK: {{^}}uniform float eyeSign;
// CHECK-NEXT: {{^}}uniform float separation;
// CHECK-NEXT: {{^}}uniform float convergence;
// CHECK: main_stereoshift_mono();
// CHECK-NEXT: if (eyeSign != 0.0 && abs(gl_Position.w - 1.0) > 9.99999975e-06 && !isinf(gl_Position.w))
// CHECK: gl_Position.x = gl_Position.x + (eyeSign * separation) * (gl_Position.w - convergence);
// CHECK-NOT: gl_DefaultUniformBlock
}
