// --eye-source=push-constant merges the three floats into the shader's own push-constant block
// (one per entry point is allowed), right after its last member: vec3 tint ends at 76. The source
// splice inserts them into the block's own text, at those offsets; SPIRV-Cross's re-emit (an explicit
// --target-version) declares the same members.
// RUN: %stereoshift --verify --eye-source push-constant %s -o - --report %t.json 2>%t.notes | %rmchecks | FileCheck %s --check-prefix=SPLICE
// RUN: FileCheck %s --check-prefix=NOTE --allow-empty --input-file %t.notes
// NOTE-NOT: re-emitted
// SPLICE: layout(push_constant) uniform Object { mat4 model; vec3 tint; /* ---- stereoshift ---- */ layout(offset = 76) float eyeSign; layout(offset = 80) float separation; layout(offset = 84) float convergence; /* ---- end stereoshift ---- */ } object;
// SPLICE: if (object.eyeSign != 0.0
// RUN: %stereoshift --eye-source push-constant --target-version 450 %s -o - | %rmchecks | FileCheck %s
// RUN: %stereoshift --eye-source push-constant --target spirv-asm %s -o - | %rmchecks | FileCheck %s --check-prefix=SPIRV
// RUN: FileCheck %s --check-prefix=REPORT --input-file %t.json
#version 450
layout(push_constant) uniform Object { mat4 model; vec3 tint; } object;
layout(set = 0, binding = 0) uniform Camera { mat4 viewProj; } camera;
layout(location = 0) in vec3 inPosition;
void main() {
  gl_Position = camera.viewProj * object.model * vec4(inPosition + object.tint, 1.0);
}
// CHECK-NOT: StereoParams
// CHECK: layout(push_constant, std430) uniform Object
// CHECK-NEXT: {
// CHECK-NEXT: mat4 model;
// CHECK-NEXT: vec3 tint;
// CHECK-NEXT: float eyeSign;
// CHECK-NEXT: float separation;
// CHECK-NEXT: float convergence;
// CHECK-NEXT: } object;
// CHECK-NOT: StereoParams
// CHECK: object.eyeSign * object.separation
// SPIRV-DAG: OpMemberDecorate %Object 1 Offset 64
// SPIRV-DAG: OpMemberDecorate %Object 2 Offset 76
// SPIRV-DAG: OpMemberDecorate %Object 3 Offset 80
// SPIRV-DAG: OpMemberDecorate %Object 4 Offset 84
// SPIRV-DAG: %Object = OpTypeStruct %mat4v4float %v3float %float %float %float
// REPORT: "declared": "push constants",
// REPORT: "offset": 76,
