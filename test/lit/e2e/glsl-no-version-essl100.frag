// A WebGL 1 / ESSL 100 fragment shader without #version (default precision statement, varying,
// gl_FragColor, texture2D) is GLSL, never taken for HLSL; the report says why.
// RUN: rm -rf %t && mkdir -p %t
// RUN: %stereoshift %s -o %t/out.frag --report %t/report.json 2> %t/log.txt || true
// RUN: FileCheck %s --input-file %t/report.json
// RUN: FileCheck %s --allow-empty --check-prefix=LOG --input-file %t/log.txt
precision mediump float;
varying vec2 vTextureCoord;
uniform sampler2D uSampler;
uniform float uAlpha;
void main(void) {
  vec4 texel = texture2D(uSampler, vTextureCoord);
  gl_FragColor = vec4(texel.rgb, texel.a * uAlpha);
}
// CHECK: "language": "glsl",
// CHECK-NEXT: "language_reason": "no #version; GLSL constructs: precision, mediump, varying, vec2, ... (HLSL 0, GLSL {{[0-9]+}})",
// CHECK-NEXT: "language_source": "content",
// LOG-NOT: entry point
// LOG-NOT: HLSL constructs
