// HLSL: an #include of a file that includes itself stops with the include chain (it used to
// include forever).
// RUN: %not timeout 300 %stereoshift %s -o %t.out 2>&1 | FileCheck %s
// RUN: test ! -e %t.out
// CHECK: {{.*}}Inputs/cycle/x.hlsli:3:1: error: #include cycle: {{.*}}include-cycle.vert.hlsl -> {{.*}}Inputs/cycle/x.hlsli -> {{.*}}Inputs/cycle/x.hlsli{{$}}
// CHECK-NEXT: #include "x.hlsli"
// CHECK-NEXT: {{^[[:blank:]]*\^$}}
// CHECK-NEXT: {{^}}1 error generated.
#include "Inputs/cycle/x.hlsli"
float4 main(float4 position : POSITION) : SV_Position {
  return position * helper(1.0);
}
