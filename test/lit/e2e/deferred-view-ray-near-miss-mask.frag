// Near misses that look like an interpolated ray times a depth read: a text shader's vertex colour
// times the glyph coverage (a vec4: no view ray) and an interpolated normal scaled by a height
// texel in a shader with no projection matrix. Neither is fixed; the vec3 one, which could be a
// frustum-corner ray, is reported for a person to check.
// RUN: %stereoshift --validate-each %s --report %t.json -o %t.out.frag
// RUN: cmp %s %t.out.frag
// RUN: FileCheck %s --input-file %t.json
#version 330 core
uniform sampler2D glyphAtlas;
uniform sampler2D heightMap;
in vec4 vColor;
in vec3 vNormal;
in vec2 vUV;
out vec4 fragColor;
void main() {
  vec4 text = vColor * texture(glyphAtlas, vUV).r;
  vec3 bumped = vNormal * texture(heightMap, vUV).r;
  fragColor = text + vec4(bumped, 0.0);
}
// CHECK: "deferred-unprojection": {
// CHECK-NEXT: "left_alone": [
// CHECK-NEXT: {
// CHECK-NEXT: "construct": "interpolated vector * texel",
// CHECK-NEXT: "depth": "heightMap",
// CHECK-NEXT: "form": "view ray interpolated from the vertex stage (vNormal)",
// CHECK-NEXT: "reason": "no projection in the shader
// CHECK-NOT: glyphAtlas
// CHECK: "result": "unchanged"
