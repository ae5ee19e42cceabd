// A WebGL 1 / ESSL 100 vertex shader without #version (attribute, varying, precision, loose
// uniforms) in a stage-named file is GLSL, never taken for HLSL: the report says GLSL and why.
// Whether ESSL 100 converts is another matter; the language decision holds either way.
// RUN: rm -rf %t && mkdir -p %t
// RUN: %stereoshift %s -o %t/out.vert --report %t/report.json 2> %t/log.txt || true
// RUN: FileCheck %s --input-file %t/report.json
// RUN: FileCheck %s --allow-empty --check-prefix=LOG --input-file %t/log.txt
precision highp float;
attribute vec3 aVertexPosition;
attribute vec2 aTextureCoord;
uniform mat4 uModelViewMatrix;
uniform mat4 uProjectionMatrix;
varying highp vec2 vTextureCoord;
float saturate(float x) { return clamp(x, 0.0, 1.0); }
void main(void) {
  gl_Position = uProjectionMatrix * uModelViewMatrix * vec4(aVertexPosition, 1.0);
  vTextureCoord = vec2(aTextureCoord.s, saturate(aTextureCoord.t));
}
// CHECK: "language": "glsl",
// CHECK-NEXT: "language_reason": "no #version; GLSL constructs: precision, highp, attribute, vec3, ... (HLSL 0, GLSL {{[0-9]+}})",
// CHECK-NEXT: "language_source": "content",
// LOG-NOT: entry point
// LOG-NOT: HLSL constructs
