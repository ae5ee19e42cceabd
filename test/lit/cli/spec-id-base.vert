// --spec-id-base sets the SpecId of eyeSign; separation and convergence follow it.
// RUN: %stereoshift --verify --eye-source spec-constant --spec-id-base 7 %s -o - | %rmchecks | FileCheck %s
// RUN: %stereoshift --eye-source spec-constant --spec-id-base 7 --target spirv-asm %s -o - | %rmchecks | FileCheck %s --check-prefix=SPIRV
#version 450
layout(constant_id = 0) const float scale = 1.0;
layout(set = 0, binding = 0) uniform Camera { mat4 viewProj; } camera;
layout(location = 0) in vec3 inPosition;
void main() {
  gl_Position = camera.viewProj * vec4(inPosition * scale, 1.0);
}
// CHECK-DAG: layout(constant_id = 0) const float scale = 1.0;
// CHECK-DAG: layout(constant_id = 7) const float eyeSign = 0.0;
// CHECK-DAG: layout(constant_id = 8) const float separation = 0.0;
// CHECK-DAG: layout(constant_id = 9) const float convergence = 1.0;
// SPIRV-DAG: OpDecorate %eyeSign SpecId 7
// SPIRV-DAG: OpDecorate %separation SpecId 8
// SPIRV-DAG: OpDecorate %convergence SpecId 9
