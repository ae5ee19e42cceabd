// Near miss: a forward shader scales an interpolated view-space vector by a depth-like scalar
// that is not a depth read back (the fragment's own depth from gl_FragCoord, for fog), and reads
// projection[0][0]: no view ray meets a depth texel, so the shader is left as it is.
// RUN: %stereoshift --validate-each %s --report %t.json -o %t.out.frag
// RUN: cmp %s %t.out.frag
// RUN: FileCheck %s --input-file %t.json
#version 330 core
uniform mat4 projection;
uniform float fogDensity;
in vec3 vViewPos;
out vec4 color;
void main() {
  float fogDepth = gl_FragCoord.z / gl_FragCoord.w;
  vec3 scaled = vViewPos * (fogDepth * fogDensity);
  color = vec4(scaled * projection[0][0], 1.0);
}
// CHECK: "deferred-unprojection": {
// CHECK-NEXT: "result": "unchanged"
