// --fused-shift computes the shift as one fused multiply-add of eyeSign * separation, w - convergence
// and x, in the spliced text as in the re-emitted one.
// RUN: %stereoshift --verify --fused-shift %s -o - | %rmchecks | FileCheck %s
// RUN: %stereoshift --verify --fused-shift --force-reemit %s -o - | %rmchecks | FileCheck %s --check-prefix=REEMIT
// RUN: %stereoshift --fused-shift --target spirv-asm %s -o - | %rmchecks | FileCheck %s --check-prefix=SPIRV
// RUN: %stereoshift %s -o - | %rmchecks | FileCheck %s --check-prefix=DEFAULT
// Below GLSL 400 / ESSL 320 there is no fma for the splice to write: a 330 source is re-emitted by
// SPIRV-Cross instead, with a note that says why.
// RUN: %stereoshift --verify --fused-shift %S/Inputs/gl330.vert -o - 2>%t.330.notes | FileCheck %s --check-prefix=GL330
// RUN: FileCheck %s --check-prefix=GL330NOTE --input-file %t.330.notes
// GL330NOTE: gl330.vert: note: GLSL re-emitted by SPIRV-Cross instead of spliced into its own text: --fused-shift needs fma (GLSL 400, ESSL 320)
// GL330: {{^}}#version 330{{$}}
// GL330-NOT: main_stereoshift_mono
// GL330: float [[S:_[0-9]+]] = eyeSign * separation;
// GL330-NEXT: float [[X:_[0-9]+]] = [[S]] * {{_[0-9]+}} + gl_Position.x;
// GL330-NEXT: gl_Position.x = [[X]];
#version 450
layout(set = 0, binding = 0) uniform Camera { mat4 viewProj; } camera;
layout(location = 0) in vec3 inPosition;
void main() {
  gl_Position = camera.viewProj * vec4(inPosition, 1.0);
}
// CHECK: precise float stereoshift_x = fma(stereo.eyeSign * stereo.separation, gl_Position.w - stereo.convergence, gl_Position.x);
// CHECK-NEXT: gl_Position.x = stereoshift_x;
// REEMIT: precise float [[S:_[0-9]+]] = stereo.eyeSign * stereo.separation;
// REEMIT-NEXT: precise float [[X:_[0-9]+]] = fma([[S]], {{_[0-9]+}}, gl_Position.x);
// REEMIT-NEXT: gl_Position.x = [[X]];
// SPIRV: OpExtInst %float {{%[0-9]+}} Fma
// SPIRV-NOT: OpFAdd %float
// DEFAULT-NOT: fma(
