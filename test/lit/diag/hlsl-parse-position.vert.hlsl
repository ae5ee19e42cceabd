// RUN: %not %stereoshift %s -o %t.out 2>&1 | FileCheck %s
// RUN: test ! -e %t.out
// An HLSL file with a stray `}`: glslang's HLSL parser says where it stopped (its own log form,
// "file(line): error at column N, ..."), and the error keeps that line and column instead of
// "glslang could not parse the shader" with no position.
// CHECK: hlsl-parse-position.vert.hlsl:15:1: error: HLSL parsing failed at '}'
// CHECK-NEXT: }
// CHECK-NEXT: {{^[[:blank:]]*\^$}}
// CHECK-NEXT: {{^}}1 error generated.
// CHECK-NOT: could not parse
cbuffer Camera : register(b0) { float4x4 viewProj; };
float4 main(float3 position : POSITION) : SV_Position {
    return mul(viewProj, float4(position, 1.0));
}
}
