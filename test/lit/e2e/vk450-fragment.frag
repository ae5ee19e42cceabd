// A fragment shader gets no shift and no eye parameters: byte-for-byte copy.
// RUN: %stereoshift --verify %s -o %t.out.frag --report %t.json
// RUN: cmp %s %t.out.frag
// RUN: FileCheck %s --input-file %t.json
// CHECK: "classification": "no-position-stage",
// CHECK: "output": "copied",
// CHECK: "stage": "frag",
#version 450
layout(set = 0, binding = 0) uniform sampler2D albedo;
layout(location = 0) in vec2 vUV;
layout(location = 0) out vec4 outColor;
void main() {
  outColor = texture(albedo, vUV);
}
