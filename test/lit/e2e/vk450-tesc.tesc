// A tessellation-control shader is never shifted (its per-vertex positions are not final): it
// comes back byte for byte, classified no-position-stage.
// RUN: %stereoshift --verify %s -o %t.out.tesc --report %t.json
// RUN: cmp %s %t.out.tesc
// RUN: FileCheck %s --input-file %t.json
// CHECK: "changed": false,
// CHECK: "classification": "no-position-stage",
// CHECK: "output": "copied",
// CHECK: "stage": "tesc",
#version 450
layout(vertices = 3) out;
layout(location = 0) in vec3 inPos[];
layout(location = 0) out vec3 outPos[];
void main() {
  outPos[gl_InvocationID] = inPos[gl_InvocationID];
  gl_out[gl_InvocationID].gl_Position = vec4(inPos[gl_InvocationID], 1.0);
  if (gl_InvocationID == 0) {
    gl_TessLevelOuter[0] = 4.0;
    gl_TessLevelOuter[1] = 4.0;
    gl_TessLevelOuter[2] = 4.0;
    gl_TessLevelInner[0] = 4.0;
  }
}
