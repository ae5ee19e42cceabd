// -I adds an #include search directory; without it the include is not found.
// RUN: %stereoshift --verify -I %S/Inputs/include-dir %s -o - | %rmchecks | FileCheck %s
// RUN: %stereoshift --verify -I%S/Inputs/include-dir %s -o - | %rmchecks | FileCheck %s
// RUN: %not %stereoshift %s -o %t.out 2>&1 | FileCheck %s --check-prefix=MISSING
// RUN: test ! -e %t.out
#version 450
#extension GL_GOOGLE_include_directive : require
#include "clip.glsl"
// MISSING: include-dir.vert:[[@LINE-1]]:1: error: '#include' : Could not process include directive for header name: clip.glsl
layout(set = 0, binding = 0) uniform Camera { mat4 viewProj; } camera;
layout(location = 0) in vec3 inPosition;
void main() {
  gl_Position = toClip(camera.viewProj, inPosition);
}
// The spliced output keeps the #include (the driver resolves it as it did for the input).
// CHECK: #include "clip.glsl"
// CHECK: void main_stereoshift_mono()
// CHECK: toClip(
// CHECK: stereo.eyeSign * stereo.separation
