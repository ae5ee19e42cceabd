// deferred-unprojection, world form: q = InvViewProj * vec4(ndc, depth, 1) with ndc from gl_FragCoord
// and a Vulkan [0,1] depth as sampled. q is replaced by
// eyeSign != 0 ? q - InvViewProj[0] * (eyeSign*separation)*(1 - convergence*q.w) : q
// right after the product, before the divide, and every use of q reads the corrected value.
// RUN: %stereoshift --validate-each %s --target spirv-asm --report %t.json -o - | FileCheck %s
// RUN: FileCheck %s --check-prefix=REPORT --input-file %t.json
#version 450
layout(set = 0, binding = 0) uniform Frame { mat4 invViewProj; vec4 viewportSize; } frame;
layout(set = 0, binding = 1) uniform sampler2D gDepth;
layout(location = 0) in vec2 inUV;
layout(location = 0) out vec4 outColor;
void main() {
  float depth = texture(gDepth, inUV).r;
  vec2 ndc = gl_FragCoord.xy * frame.viewportSize.zw * 2.0 - 1.0;
  vec4 q = frame.invViewProj * vec4(ndc, depth, 1.0);
  outColor = vec4(q.xyz / q.w, 1.0);
}
// The eye parameters come as a uniform block at the next free binding of set 0.
// CHECK: OpMemberName %StereoParams 0 "eyeSign"
// CHECK: OpDecorate %stereo Binding 2
// CHECK: [[M:%[0-9]+]] = OpLoad %mat4v4float
// CHECK: [[V:%[0-9]+]] = OpCompositeConstruct %v4float {{%[0-9]+}} {{%[0-9]+}} {{%[0-9]+}} %float_1
// CHECK-NEXT: [[Q:%[0-9]+]] = OpMatrixTimesVector %v4float [[M]] [[V]]
// CHECK-NEXT: [[COL0:%[0-9]+]] = OpCompositeExtract %v4float [[M]] 0
// CHECK: [[E:%[0-9]+]] = OpLoad %float
// CHECK: [[S:%[0-9]+]] = OpLoad %float
// CHECK: [[C:%[0-9]+]] = OpLoad %float
// CHECK-NEXT: [[QW:%[0-9]+]] = OpCompositeExtract %float [[Q]] 3
// CHECK-NEXT: [[CQW:%[0-9]+]] = OpFMul %float [[C]] [[QW]]
// CHECK-NEXT: [[PAR:%[0-9]+]] = OpFSub %float %float_1 [[CQW]]
// CHECK-NEXT: [[ES:%[0-9]+]] = OpFMul %float [[E]] [[S]]
// CHECK-NEXT: [[K:%[0-9]+]] = OpFMul %float [[ES]] [[PAR]]
// CHECK-NEXT: [[CORR:%[0-9]+]] = OpVectorTimesScalar %v4float [[COL0]] [[K]]
// CHECK-NEXT: [[FIXED:%[0-9]+]] = OpFSub %v4float [[Q]] [[CORR]]
// CHECK-NEXT: [[STEREO:%[0-9]+]] = OpFUnordNotEqual %bool [[E]] %float_0
// CHECK-NEXT: [[STEREO4:%[0-9]+]] = OpCompositeConstruct %v4bool [[STEREO]] [[STEREO]] [[STEREO]] [[STEREO]]
// CHECK-NEXT: [[QF:%[0-9]+]] = OpSelect %v4float [[STEREO4]] [[FIXED]] [[Q]]
// CHECK-NEXT: OpStore %q [[QF]]
// CHECK-NOT: [[Q]]
// CHECK: OpFunctionEnd

// REPORT: "deferred-unprojection": {
// REPORT-NEXT: "fixed": [
// REPORT-NEXT: {
// REPORT-NEXT: "depth": "gDepth",
// REPORT-NEXT: "depth_range": "as sampled ([0, 1])",
// REPORT-NEXT: "fix": "q - frame.invViewProj[col 0] * eyeSign*separation*(1 - convergence*q.w), before the divide",
// REPORT-NEXT: "form": "world position from an inverse view-projection",
// REPORT-NEXT: "matrix": "frame.invViewProj",
// REPORT-NEXT: "ndc": "gl_FragCoord"
// REPORT-NEXT: }
// REPORT-NEXT: ],
// REPORT-NEXT: "result": "changed"
