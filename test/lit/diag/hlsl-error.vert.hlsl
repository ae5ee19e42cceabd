// An HLSL error is reported at its line:col as well.
// RUN: %not %stereoshift %s -o %t.out 2>&1 | FileCheck %s
// RUN: test ! -e %t.out
float4 main(float3 p : POSITION) : SV_Position
{
  return float4(p, undefinedVar);
// CHECK: hlsl-error.vert.hlsl:[[@LINE-1]]:20: error: 'undefinedVar' : unknown variable
}
// CHECK: {{^[0-9]+}} errors generated.
