// verify on a shader that needs no injection says so and succeeds; on an unreadable file it fails.
// RUN: %stereoshift verify %S/../e2e/Inputs/fullscreen-2d.vert | FileCheck %s
// RUN: %not %stereoshift verify %s 2>&1 | FileCheck %s --check-prefix=FRAG
#version 450
layout(location = 0) out vec4 color;
void main() { color = vec4(1.0); }
// CHECK: 2d-constant-w: nothing is injected, nothing to verify
// FRAG: error: nothing to verify: no vertex, tessellation or geometry stage
// FRAG: 1 error generated.
