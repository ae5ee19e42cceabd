// halo by value must not fire on a different matrix: a shadow-map coordinate (DepthBiasMVP * p)
// is not a copy of the position (mvp * p), however alike the two products look.
// RUN: %stereoshift --validate-each --verify %s -o %t.vert --report %t.json
// RUN: FileCheck %s --input-file %t.vert
// RUN: FileCheck %s --check-prefix=REPORT --input-file %t.json
// CHECK: outShadowCoord = scene.depthBiasMVP * vec4(inPos, 1.0);
// REPORT: "halo": {
// REPORT-NEXT: "result": "unchanged",
// REPORT-NEXT: "shifted_outputs": []
#version 450
layout(set = 0, binding = 0) uniform Scene { mat4 mvp; mat4 depthBiasMVP; } scene;
layout(location = 0) in vec3 inPos;
layout(location = 0) out vec4 outShadowCoord;
void main() {
  outShadowCoord = scene.depthBiasMVP * vec4(inPos, 1.0);
  gl_Position = scene.mvp * vec4(inPos, 1.0);
}
