#version 110
// A GL 2.x fragment shader with compatibility inputs (gl_Color, gl_TexCoord) and gl_FragColor:
// nothing per-eye, so it is copied byte for byte.
// RUN: %stereoshift %s -o %t.frag --report %t.json
// RUN: cmp %s %t.frag
// RUN: FileCheck %s --input-file %t.json
// CHECK: "classification": "no-position-stage"
// CHECK: "output": "copied"
uniform sampler2D texture;
void main() {
    gl_FragColor = gl_Color * texture2D(texture, gl_TexCoord[0].st);
}
