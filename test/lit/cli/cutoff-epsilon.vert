// --cutoff-epsilon sets the tolerance of the w != 1 cutoff: |w - 1| > 0.001 here.
// RUN: %stereoshift --verify --cutoff-epsilon 0.001 %s -o - | %rmchecks | FileCheck %s
// RUN: %stereoshift --cutoff-epsilon 0.001 --target spirv-asm %s -o - | %rmchecks | FileCheck %s --check-prefix=SPIRV
// RUN: %stereoshift --verify %s -o - | %rmchecks | FileCheck %s --check-prefix=DEFAULT
#version 450
layout(set = 0, binding = 0) uniform Camera { mat4 viewProj; } camera;
layout(location = 0) in vec3 inPosition;
void main() {
  gl_Position = camera.viewProj * vec4(inPosition, 1.0);
}
// CHECK: if (stereo.eyeSign != 0.0 && abs(gl_Position.w - 1.0) > 0.00100000005 && !isinf(gl_Position.w))
// SPIRV: %float_0_00100000005 = OpConstant %float 0.00100000005
// SPIRV: OpExtInst %float {{%[0-9]+}} FAbs
// SPIRV-NEXT: OpFOrdGreaterThan %bool {{%[0-9]+}} %float_0_00100000005
// DEFAULT: if (stereo.eyeSign != 0.0 && abs(gl_Position.w - 1.0) > 9.99999975e-06 && !isinf(gl_Position.w))
