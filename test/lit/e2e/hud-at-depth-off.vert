// Without --hud-at-depth a proven-2D shader stays mono: nothing injected, copied byte for byte.
// RUN: %stereoshift --validate-each %s --report %t.json -o %t.out.vert
// RUN: cmp %s %t.out.vert
// RUN: FileCheck %s --input-file %t.json
// With the option the same shader is placed at depth (so the option is what changes it); the source
// splice cannot carry that change, so SPIRV-Cross re-emits it and the report's notes say so.
// RUN: %stereoshift --hud-at-depth --validate-each %s --report - -o %t.hud.vert | FileCheck %s --check-prefix=ON
#version 450
layout(set = 0, binding = 0) uniform Panel { vec4 rect; } panel;
layout(location = 0) in vec2 inCorner;
void main() {
  gl_Position = vec4(panel.rect.xy + inCorner * panel.rect.zw, 0.0, 1.0);
}
// CHECK: "classification": "2d-constant-w",
// CHECK: "output": "copied",
// CHECK: "hud-at-depth": {
// CHECK-NEXT: "result": "unchanged"
// CHECK-NEXT: },
// ON: "notes": [
// ON-NEXT: "GLSL re-emitted by SPIRV-Cross instead of spliced into its own text: the splice cannot carry what the hud-at-depth pass changed"
// ON-NEXT: ],
// ON: "output": "emitted",
// ON: "hud-at-depth": {
// ON: "result": "changed",
