// --eye-source=loose-uniforms asks for loose OpenGL uniforms even in a GL shader that only uses a
// uniform block (where the default would be the uniform block).
// RUN: %stereoshift --verify --eye-source loose-uniforms %s -o - | %rmchecks | FileCheck %s
// RUN: %stereoshift --verify %s -o - | %rmchecks | FileCheck %s --check-prefix=AUTO
#version 330
layout(std140) uniform Camera { mat4 viewProj; } camera;
in vec3 aPosition;
void main() {
  gl_Position = camera.viewProj * vec4(aPosition, 1.0);
}
// CHECK-NOT: StereoParams
// CHECK-DAG: {{^}}uniform float eyeSign;
// CHECK-DAG: {{^}}uniform float separation;
// CHECK-DAG: {{^}}uniform float convergence;
// CHECK: if (eyeSign != 0.0 && abs(gl_Position.w - 1.0) > 9.99999975e-06 && !isinf(gl_Position.w))
// CHECK: gl_Position.x = gl_Position.x + (eyeSign * separation) * (gl_Position.w - convergence);
// AUTO: uniform StereoParams
// AUTO-NOT: {{^}}uniform float eyeSign;
// AUTO: stereo.eyeSign * stereo.separation
