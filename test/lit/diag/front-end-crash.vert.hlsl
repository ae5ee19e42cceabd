// RUN: %not %stereoshift %s -o %t.out 2>&1 | FileCheck %s
// RUN: test ! -e %t.out
// RUN: rm -rf %t.dir && mkdir -p %t.dir/src && cp %s %t.dir/src/ && cp %S/Inputs/ok.vert %t.dir/src/
// RUN: %not %stereoshift build %t.dir/src -o %t.dir/out 2>&1 | FileCheck %s --check-prefix=BUILD
// RUN: test -e %t.dir/out/ok.vert && test ! -e %t.dir/out/front-end-crash.vert.hlsl
// glslang's HLSL front end crashes on a global variable named like a struct (packaged glslang
// 11-14). The conversion runs in a child that says which phase it is in: the error says the front
// end crashed on this input (not "stereoshift crashed"), and a note names the construct.
// CHECK: front-end-crash.vert.hlsl: error: the front end (glslang, parsing HLSL) crashed on this input (signal 11, SIGSEGV) while converting this shader; no output was written
// CHECK-NEXT: front-end-crash.vert.hlsl:16:8: note: a global variable named like the struct 'Camera' (glslang's HLSL front end crashes on it; rename one of them)
// CHECK-NOT: stereoshift crashed
// In a tree, the same words for that pipeline; the other shaders convert.
// BUILD: front-end-crash.vert.hlsl: error: the conversion of pipeline 'front-end-crash' (front-end-crash.vert.hlsl) failed: the front end (glslang, parsing HLSL) crashed on this input (signal 11, SIGSEGV); the other shaders are converted regardless
// BUILD-NEXT: front-end-crash.vert.hlsl:16:8: note: a global variable named like the struct 'Camera'
struct Camera { float4x4 viewProj; };
float4 Camera;
float4 main(float3 position : POSITION) : SV_Position { return float4(position, 1.0); }
