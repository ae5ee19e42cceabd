// --eye-source=uniform-block asks for the injected block even in a GL shader whose other
// uniforms are loose (where the default would be loose uniforms).
// RUN: %stereoshift --verify --eye-source uniform-block %s -o - | %rmchecks | FileCheck %s
// RUN: %stereoshift --verify --eye-source=uniform-block %s -o - | %rmchecks | FileCheck %s
// RUN: %stereoshift --verify %s -o - | %rmchecks | FileCheck %s --check-prefix=AUTO
#version 330
uniform mat4 uMVP;
in vec3 aPosition;
void main() {
  gl_Position = uMVP * vec4(aPosition, 1.0);
}
// CHECK: {{^}}uniform mat4 uMVP;
// CHECK: layout(std140) uniform StereoParams
// CHECK-NEXT: {
// CHECK-NEXT: float eyeSign;
// CHECK-NEXT: float separation;
// CHECK-NEXT: float convergence;
// CHECK-NEXT: } stereo;
// CHECK-NOT: uniform float eyeSign;
// CHECK: stereo.eyeSign * stereo.separation
// AUTO-NOT: StereoParams
// AUTO: {{^}}uniform float eyeSign;
