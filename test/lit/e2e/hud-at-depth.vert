// --hud-at-depth: a proven-2D vertex shader (literal w = 1) gets its position placed at the eye
// depth `hudDepth`: pos * hudDepth = vec4(xy*d, z*d, d) (z*d keeps the NDC depth, so the depth test
// decides as before), then the usual shift, which gives the element the parallax e*S*(1 - C/d).
// RUN: %stereoshift --hud-at-depth --validate-each %s --target spirv-asm --report %t.json -o - | FileCheck %s
// RUN: FileCheck %s --check-prefix=REPORT --input-file %t.json
#version 450
layout(set = 0, binding = 0) uniform Panel { vec4 rect; } panel;
layout(location = 0) in vec2 inCorner;
void main() {
  gl_Position = vec4(panel.rect.xy + inCorner * panel.rect.zw, 0.0, 1.0);
}
// CHECK: OpMemberName %StereoParams 3 "hudDepth"
// CHECK: OpMemberDecorate %StereoParams 3 Offset 12
// CHECK: [[POS:%[0-9]+]] = OpCompositeConstruct %v4float {{%[0-9]+}} {{%[0-9]+}} %float_0 %float_1
// CHECK-NEXT: [[PTR:%[0-9]+]] = OpAccessChain %_ptr_Output_v4float
// CHECK-NEXT: [[D:%[0-9]+]] = OpAccessChain %_ptr_Uniform_float %stereo %int_3
// CHECK-NEXT: [[DEPTH:%[0-9]+]] = OpLoad %float [[D]]
// CHECK-NEXT: [[PLACED:%[0-9]+]] = OpVectorTimesScalar %v4float [[POS]] [[DEPTH]]
// CHECK-NEXT: OpStore [[PTR]] [[PLACED]]
// The shift follows, as for any perspective position.
// CHECK: OpSelectionMerge
// CHECK: OpStore {{%[0-9]+}} {{%[0-9]+}}
// CHECK-NEXT: OpBranch

// REPORT: "classification": "2d-constant-w"
// REPORT: "hud-at-depth": {
// REPORT-NEXT: "note": "the w != 1 cutoff also applies here
// REPORT-NEXT: "placed_at_depth": [
// REPORT-NEXT: "gl_PerVertex.gl_Position"
// REPORT-NEXT: ],
// REPORT-NEXT: "position": "vec4(pos.xy * hudDepth, pos.z * hudDepth, hudDepth)",
// REPORT-NEXT: "result": "changed",
// REPORT-NEXT: "stores": 1
// REPORT: "stereo-shift": {
// REPORT-NEXT: "form": "branch",
// REPORT-NEXT: "result": "changed",
