// An -e entry point the file does not define is an error that names it, with no output file.
// RUN: %not %stereoshift -e NoSuchEntry %s -o %t.out 2>&1 | FileCheck %s
// RUN: test ! -e %t.out
// CHECK: unknown-entry-point.vert.hlsl: error: {{.*}}'NoSuchEntry'
// CHECK: {{^}}1 error generated.
float4 VSMain(float3 pos : POSITION) : SV_Position
{
  return float4(pos, 2.0);
}
