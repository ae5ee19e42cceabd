// Constructs that see the per-eye pixel or the mono eye but are not unprojections are left alone
// and listed in the report for a person to check by eye: a gl_FragCoord-based dither reaching the
// output, and a reflection vector. A G-buffer read at the pixel (gl_FragCoord as a texture
// coordinate) is per-eye already and is not listed.
// RUN: %stereoshift --validate-each %s --report %t.json -o %t.out.frag
// RUN: cmp %s %t.out.frag
// RUN: FileCheck %s --input-file %t.json
#version 450
layout(set = 0, binding = 0) uniform sampler2D gNormal;
layout(set = 0, binding = 1) uniform samplerCube environment;
layout(location = 0) in vec3 vViewDirection;
layout(location = 0) out vec4 outColor;
layout(location = 1) out vec4 outNormal;
void main() {
  vec3 n = texelFetch(gNormal, ivec2(gl_FragCoord.xy), 0).xyz;
  outNormal = vec4(n, 0.0);
  vec3 r = reflect(normalize(vViewDirection), n);
  float dither = fract(dot(gl_FragCoord.xy, vec2(0.0671, 0.00584)) * 52.98) / 255.0;
  outColor = texture(environment, r) + dither;
}
// CHECK: "output": "copied",
// CHECK: "deferred-unprojection": {
// CHECK-NEXT: "left_alone": [
// CHECK-NEXT: {
// CHECK-NEXT: "construct": "gl_FragCoord",
// CHECK-NEXT: "reaches": "outColor",
// CHECK-NEXT: "reason": "screen-space computation from this eye's pixel position, left as it is: check by eye"
// CHECK-NEXT: },
// CHECK-NEXT: {
// CHECK-NEXT: "construct": "reflect()",
// CHECK-NEXT: "count": 1,
// CHECK: "result": "unchanged"
