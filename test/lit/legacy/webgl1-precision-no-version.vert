// No #version but a precision statement (OpenGL ES only): the shader is WebGL1's ESSL 100, and the
// output is re-compiled as ESSL 100.
// RUN: %stereoshift %s -o %t.vert --report %t.json
// RUN: FileCheck %s --input-file %t.json
// RUN: glslangValidator -S vert %t.vert
// CHECK: "dialect": "100 es"
// CHECK: "dialect_reason": "no #version; uses `precision` (OpenGL ES only), so ESSL 100 (WebGL1)"
precision highp float;
attribute vec3 aPosition;
uniform mat4 uModelViewProjection;
void main() {
  gl_Position = uModelViewProjection * vec4(aPosition, 1.0);
}
