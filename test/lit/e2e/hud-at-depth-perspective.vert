// --hud-at-depth changes only proven-2D shaders: a perspective shader gets the usual shift and
// nothing else (no hudDepth parameter, the same output as without the option).
// RUN: %stereoshift --hud-at-depth --validate-each %s --report %t.json -o %t.hud.vert
// RUN: %stereoshift --validate-each %s -o %t.plain.vert
// RUN: cmp %t.hud.vert %t.plain.vert
// RUN: FileCheck %s --input-file %t.json
// RUN: %rmchecks %t.hud.vert | FileCheck %s --check-prefix=OUT
#version 450
layout(set = 0, binding = 0) uniform Camera { mat4 viewProj; } camera;
layout(location = 0) in vec3 inPosition;
void main() {
  gl_Position = camera.viewProj * vec4(inPosition, 1.0);
}
// CHECK: "classification": "perspective",
// CHECK: "hud-at-depth": {
// CHECK-NEXT: "result": "unchanged"
// CHECK-NEXT: },
// OUT: float convergence;
// OUT-NOT: hudDepth
