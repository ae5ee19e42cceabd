// -D defines preprocessor macros, as -DNAME, -DNAME=VALUE and -D NAME=VALUE. The spliced output
// keeps the #ifdef and the macro as written (the driver sees the same -D); the re-emit, which
// writes what glslang parsed, has them expanded.
// RUN: %stereoshift --verify -DSCALED -DSCALE=2.5 %s -o - | %rmchecks | FileCheck %s --check-prefix=SCALED
// RUN: %stereoshift --verify -D SCALED -D SCALE=2.5 %s -o - | %rmchecks | FileCheck %s --check-prefix=SCALED
// RUN: %stereoshift --verify %s -o - | %rmchecks | FileCheck %s --check-prefix=PLAIN
// RUN: %stereoshift --verify --force-reemit -DSCALED -DSCALE=2.5 %s -o - | %rmchecks | FileCheck %s --check-prefix=EXPANDED
#version 450
layout(set = 0, binding = 0) uniform Camera { mat4 viewProj; } camera;
layout(location = 0) in vec3 inPosition;
void main() {
#ifdef SCALED
  gl_Position = camera.viewProj * vec4(inPosition * SCALE, 1.0);
#else
  gl_Position = camera.viewProj * vec4(inPosition, 1.0);
#endif
}
// SCALED: #ifdef SCALED
// SCALED-NEXT: gl_Position = camera.viewProj * vec4(inPosition * SCALE, 1.0);
// SCALED: stereo.eyeSign
// EXPANDED-NOT: SCALE
// EXPANDED: inPosition * 2.5
// EXPANDED: eyeSign
// PLAIN-NOT: 2.5
// PLAIN: vec4(inPosition, 1.0)
// PLAIN: eyeSign
