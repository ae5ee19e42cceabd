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
// CHECK: (eyeSign * separation)
// AUTO: uniform StereoParams
// AUTO-NOT: {{^}}uniform float eyeSign;
// AUTO: stereo.eyeSign * stereo.separation
