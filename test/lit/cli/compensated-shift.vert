// --compensated-shift computes x + eyeSign*separation*(w - convergence) with error-free
// transformations (TwoSum, Dekker's TwoProduct), every operation `precise`. The GLSL source splice
// does not write this form: the output is SPIRV-Cross's re-emit, with a note that says so.
// RUN: %stereoshift --verify --compensated-shift %s -o - 2>%t.notes | %rmchecks | FileCheck %s
// RUN: FileCheck %s --check-prefix=NOTE --input-file %t.notes
// RUN: %stereoshift verify --compensated-shift %s | FileCheck %s --check-prefix=VERIFY
// RUN: %stereoshift --compensated-shift --target glsl --target-version 330 %s -o %t.glsl 2>&1 | FileCheck %s --check-prefix=WARN
#version 450
layout(set = 0, binding = 0) uniform Camera { mat4 viewProj; } camera;
layout(location = 0) in vec3 inPosition;
void main() {
  gl_Position = camera.viewProj * vec4(inPosition, 1.0);
}
// NOTE: compensated-shift.vert: note: GLSL re-emitted by SPIRV-Cross instead of spliced into its own text: --compensated-shift is written by SPIRV-Cross
// CHECK-NOT: main_stereoshift_mono
// CHECK: precise float {{_[0-9]+}} = gl_Position.w - stereo.convergence;
// CHECK: 4097.0
// CHECK: gl_Position.x = {{_[0-9]+}};
// VERIFY: stereo x error: {{(0|0\.[0-9]+|1)}} ULP
// VERIFY: {{^}}verified
// WARN: warning: --compensated-shift needs `precise`
