// An OpenGL GLSL 330 shader with loose uniforms stays a drop-in replacement: the same loose
// uniforms (glGetUniformLocation keeps working), the eye parameters as loose uniforms too, no
// gl_DefaultUniformBlock, no SPIRV_Cross_BaseInstance for gl_InstanceID, and no layout(location)
// or layout(binding) on declarations that had none.
// RUN: %stereoshift --verify %s -o %t.out.vert
// RUN: %rmchecks %t.out.vert | FileCheck %s
// RUN: %rmchecks %t.out.vert | FileCheck %s --check-prefix=NEG
// RUN: glslangValidator %t.out.vert
#version 330 core
// CHECK: #version 330
uniform mat4 uModel;
uniform mat4 uViewProj;
uniform sampler2D uHeight;
// CHECK-DAG: {{^}}uniform mat4 uModel;
// CHECK-DAG: {{^}}uniform mat4 uViewProj;
// CHECK-DAG: {{^}}uniform sampler2D uHeight;
layout(location = 0) in vec3 aPosition;
in vec3 aOffset;
in vec2 aTexCoord;
out vec2 vTexCoord;
// CHECK-DAG: {{^}}layout(location = 0) in vec3 aPosition;
// CHECK-DAG: {{^}}in vec3 aOffset;
// CHECK-DAG: {{^}}in vec2 aTexCoord;
// CHECK-DAG: {{^}}out vec2 vTexCoord;
void main() {
  vTexCoord = aTexCoord + vec2(float(gl_InstanceID), 0.0);
  float h = texture(uHeight, aTexCoord).r;
  gl_Position = uViewProj * uModel * vec4(aPosition + aOffset + vec3(0.0, h, 0.0), 1.0);
// CHECK: void main_stereoshift_mono()
// CHECK: gl_InstanceID
// CHECK: gl_Position =
// CHECK: {{^}}uniform float eyeSign;
// CHECK-NEXT: {{^}}uniform float separation;
// CHECK-NEXT: {{^}}uniform float convergence;
// CHECK: main_stereoshift_mono();
// CHECK-NEXT: if (eyeSign != 0.0 && abs(gl_Position.w - 1.0) > 9.99999975e-06 && !isinf(gl_Position.w))
// CHECK-NEXT: {
// CHECK-NEXT: gl_Position.x = gl_Position.x + (eyeSign * separation) * (gl_Position.w - convergence);
}
// NEG: {{^}}#version 330
// NEG-NOT: gl_DefaultUniformBlock
// NEG-NOT: SPIRV_Cross_BaseInstance
// NEG-NOT: StereoParams
// NEG-NOT: layout(location = {{[1-9]}})
// NEG-NOT: binding
// NEG-NOT: #extension
// NEG: void main()
// NEG-NOT: gl_DefaultUniformBlock
// NEG-NOT: SPIRV_Cross_BaseInstance
