// --no-cutoff shifts every vertex, w == 1 ones included: no w test at all, only the mono guard
// (eyeSign != 0) remains.
// RUN: %stereoshift --verify --no-cutoff %s -o - | %rmchecks | FileCheck %s
// RUN: %stereoshift --no-cutoff --target spirv-asm %s -o - --report %t.json | %rmchecks | FileCheck %s --check-prefix=SPIRV
// RUN: FileCheck %s --check-prefix=REPORT --input-file %t.json
#version 450
layout(set = 0, binding = 0) uniform Camera { mat4 viewProj; } camera;
layout(location = 0) in vec3 inPosition;
void main() {
  gl_Position = camera.viewProj * vec4(inPosition, 1.0);
}
// Only the mono guard is left: eyeSign 0 runs none of the shift.
// CHECK: void main()
// CHECK-NOT: abs(
// CHECK-NOT: {{\) \? }}
// CHECK: if (stereo.eyeSign != 0.0)
// CHECK: stereo.eyeSign * stereo.separation
// CHECK-NOT: if (
// SPIRV-NOT: OpFOrdGreaterThan
// SPIRV-NOT: OpIsInf
// SPIRV: OpFUnordNotEqual %bool {{%[0-9]+}} %float_0
// SPIRV-NEXT: OpSelectionMerge
// SPIRV-NOT: OpSelect{{ }}
// SPIRV: OpFAdd %float
// SPIRV-NOT: OpSelect
// REPORT: "form": "branch",
