// A SPIR-V binary converted twice is left as it is the second time (byte-identical .spv).
// RUN: %stereoshift --verify --target spirv %s -o %t.1.spv
// RUN: %stereoshift %t.1.spv -o %t.2.spv 2>&1 | FileCheck %s
// RUN: cmp %t.1.spv %t.2.spv
// CHECK: note: shader already carries stereo eye parameters ('eyeSign'); left as it is, never shifted twice
#version 450
layout(set = 0, binding = 0) uniform Camera { mat4 viewProj; } camera;
layout(location = 0) in vec3 inPosition;
void main() {
  gl_Position = camera.viewProj * vec4(inPosition, 1.0);
}
