#version 300 es
// An ESSL 300 shader (which glslang 12 only turns into SPIR-V at 310) comes back as ESSL 300 with
// its loose uniforms, the eye parameters as loose uniforms, and no gl_DefaultUniformBlock.
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
// CHECK-DAG: {{^}}uniform {{(highp )?}}float eyeSign;
// CHECK-DAG: {{^}}uniform {{(highp )?}}float separation;
// CHECK-DAG: {{^}}uniform {{(highp )?}}float convergence;
in vec3 aPosition;
in vec2 aUV;
out vec2 vUV;
// CHECK-DAG: {{^}}in {{(highp )?}}vec3 aPosition;
// CHECK-DAG: {{^}}in {{(highp )?}}vec2 aUV;
// CHECK-DAG: {{^}}out {{(highp )?}}vec2 vUV;
void main() {
  vUV = aUV;
  gl_Position = uMVP * vec4(aPosition, 1.0);
// CHECK: void main()
// CHECK: vUV = aUV;
// CHECK: gl_Position =
// CHECK-NEXT: if (({{[A-Za-z_.]*}}eyeSign != 0.0{{f?}}) && ((abs(gl_Position.w - 1.0) > {{9\.9999997[0-9]*e-0*6}}) && (!isinf(gl_Position.w))))
// CHECK: float {{_[0-9]+}} = eyeSign * separation;
// CHECK: gl_Position.x =
// CHECK-NOT: gl_DefaultUniformBlock
}
