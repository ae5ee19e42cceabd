// Converting an already converted shader again gives a byte-identical file, and the tool says why:
// the StereoParams parameters it finds mean the shift is already there.
// RUN: %stereoshift --verify %s -o %t.1.vert
// RUN: %stereoshift --verify %t.1.vert -o %t.2.vert 2>&1 | FileCheck %s
// RUN: cmp %t.1.vert %t.2.vert
// RUN: %rmchecks %t.2.vert | FileCheck %s --check-prefix=ONCE
// CHECK: 1.vert: note: shader already carries stereo eye parameters ('eyeSign'); left as it is, never shifted twice
// CHECK-NOT: warning
// CHECK-NOT: error
#version 450
layout(set = 0, binding = 0) uniform Camera { mat4 viewProj; } camera;
layout(location = 0) in vec3 inPosition;
void main() {
  gl_Position = camera.viewProj * vec4(inPosition, 1.0);
}
// Exactly one StereoParams block and one shift.
// ONCE: uniform StereoParams
// ONCE-NOT: uniform StereoParams
// ONCE: stereo.eyeSign * stereo.separation
// ONCE-NOT: eyeSign
