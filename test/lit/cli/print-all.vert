// --print-all prints the SPIR-V after every pass to stderr, in pipeline order with each pass's
// result; the converted shader still goes to the output.
// RUN: %stereoshift --print-all %s -o %t.out.vert 2> %t.log
// RUN: FileCheck %s --input-file %t.log
// RUN: %rmchecks %t.out.vert | FileCheck %s --check-prefix=OUT
// RUN: %stereoshift %s -o %t.quiet.vert 2> %t.quiet.log
// RUN: FileCheck %s --check-prefix=QUIET --allow-empty --input-file %t.quiet.log
// RUN: cmp %t.out.vert %t.quiet.vert
#version 450
layout(set = 0, binding = 0) uniform Camera { mat4 viewProj; } camera;
layout(location = 0) in vec3 inPosition;
void main() {
  gl_Position = camera.viewProj * vec4(inPosition, 1.0);
}
// CHECK: ; IR after clip-position-detection (unchanged)
// CHECK-NEXT: ; SPIR-V
// CHECK-NOT: StereoParams
// CHECK: ; IR after eye-params (changed)
// CHECK: OpName %StereoParams "StereoParams"
// CHECK-NOT: OpSelectionMerge
// CHECK: ; IR after halo (unchanged)
// CHECK: ; IR after stereo-shift (changed)
// CHECK: OpFOrdGreaterThan
// CHECK: OpFunctionEnd
// OUT: uniform StereoParams
// QUIET-NOT: IR after
