// --block-name renames the injected uniform block (the instance keeps its default name).
// RUN: %stereoshift --verify --block-name EyeParams %s -o - | %rmchecks | FileCheck %s
// RUN: %stereoshift --block-name EyeParams --target spirv-asm %s -o - | %rmchecks | FileCheck %s --check-prefix=SPIRV
#version 450
layout(set = 0, binding = 0) uniform Camera { mat4 viewProj; } camera;
layout(location = 0) in vec3 inPosition;
void main() {
  gl_Position = camera.viewProj * vec4(inPosition, 1.0);
}
// CHECK-NOT: StereoParams
// CHECK: layout(set = 0, binding = 1, std140) uniform EyeParams
// CHECK-NEXT: {
// CHECK-NEXT: float eyeSign;
// CHECK: } stereo;
// CHECK-NOT: StereoParams
// CHECK: stereo.eyeSign * stereo.separation
// SPIRV: OpName %EyeParams "EyeParams"
// SPIRV: OpDecorate %EyeParams Block
