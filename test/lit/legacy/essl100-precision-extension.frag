#version 100
// ESSL 100 with a default precision statement and an extension that is core in ESSL 300: it parses
// (the extension line is dropped from the analysis translation only, fwidth works), and a fragment
// shader with nothing per-eye is copied byte for byte.
// RUN: %stereoshift %s -o %t.frag --report %t.json
// RUN: cmp %s %t.frag
// RUN: FileCheck %s --input-file %t.json
// CHECK: "dialect": "100 es"
// CHECK: "output": "copied"
#extension GL_OES_standard_derivatives : enable
precision mediump float;
varying vec2 vUv;
uniform sampler2D uTexture;
void main() {
  vec4 color = texture2D(uTexture, vUv);
  float edge = fwidth(vUv.x);
  gl_FragColor = vec4(color.rgb * edge, color.a);
}
