// --no-cutoff shifts every vertex, w == 1 ones included: no test at all, the shift is unconditional.
// RUN: %stereoshift --verify --no-cutoff %s -o - | %rmchecks | FileCheck %s
// RUN: %stereoshift --no-cutoff --target spirv-asm %s -o - --report %t.json | %rmchecks | FileCheck %s --check-prefix=SPIRV
// RUN: FileCheck %s --check-prefix=REPORT --input-file %t.json
#version 450
layout(set = 0, binding = 0) uniform Camera { mat4 viewProj; } camera;
layout(location = 0) in vec3 inPosition;
void main() {
  gl_Position = camera.viewProj * vec4(inPosition, 1.0);
}
// CHECK: void main()
// CHECK-NOT: if (
// CHECK-NOT: abs(
// CHECK-NOT: {{\) \? }}
// CHECK: stereo.eyeSign * stereo.separation
// CHECK-NOT: if (
// SPIRV-NOT: OpSelectionMerge
// SPIRV-NOT: OpFOrdGreaterThan
// SPIRV-NOT: OpSelect
// SPIRV: OpFAdd %float
// SPIRV-NOT: OpSelect
// REPORT: "form": "unconditional",
