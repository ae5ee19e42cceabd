#version 100
// ESSL 100 lets a loop index select a sampler of an array (Appendix A: a for-loop index is a
// constant-index expression), as terrain shaders blending height maps do. The analysis translation
// is ESSL 310, which allows it only with GL_EXT_gpu_shader5: the front end enables that for its own
// parse (glslang's preamble; the translation keeps every line), and the output is the original
// text plus the shift. Before, the conversion stopped at the indexing.
// RUN: %stereoshift %s -o %t.vert --report %t.json
// RUN: %rmchecks %t.vert | FileCheck %s
// RUN: FileCheck %s --check-prefix=REPORT --input-file %t.json
// CHECK: for (int i = 0; i < 4; i++) h += texture2D(uHeights[i], aUV).r * uWeights[i];
// CHECK: void main()
// CHECK: main_stereoshift_mono();
// CHECK: gl_Position.x = gl_Position.x + (eyeSign * separation) * (gl_Position.w - convergence);
// REPORT: "dialect": "100 es"
// REPORT: "route": "glsl-source-splice"
// The extension is the analysis's only: not in the output.
// RUN: %not grep -q "^#extension" %t.vert
attribute vec2 aUV;
attribute vec3 aPos;
uniform sampler2D uHeights[4];
uniform float uWeights[4];
uniform mat4 uMVP;
void main() {
  float h = 0.0;
  for (int i = 0; i < 4; i++) h += texture2D(uHeights[i], aUV).r * uWeights[i];
  gl_Position = uMVP * vec4(aPos + vec3(0.0, h, 0.0), 1.0);
}
