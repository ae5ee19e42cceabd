// A WebGL1 vertex shader with no #version and no precision statement (the vertex stage has a default)
// shows nothing ES-only; it builds a matrix from a matrix, which ESSL 100 takes and GLSL 110 does not.
// glslang refuses it as GLSL's default 110 and takes it as ESSL 100: it is ESSL 100, and converts.
// RUN: %stereoshift %s -o %t.vert --report %t.json
// RUN: %rmchecks %t.vert | FileCheck %s
// RUN: FileCheck %s --check-prefix=REPORT --input-file %t.json
// CHECK-NOT:  {{^}}#version
// CHECK:      {{^}}attribute vec3 position;
// CHECK:      {{^}}  vNormal = mat3(modelViewMatrix) * normal;
// CHECK:      {{^}}uniform float eyeSign;
// REPORT: "dialect": "100 es"
// REPORT: "dialect_reason": "no #version; glslang refuses it as GLSL 110 ({{.*}}matrix from matrix{{.*}}) and takes it as ESSL 100, so ESSL 100 (WebGL1)"
// REPORT: "verified": true
attribute vec3 position;
attribute vec3 normal;
uniform mat4 modelViewMatrix;
uniform mat4 projectionMatrix;
varying vec3 vNormal;
void main() {
  vNormal = mat3(modelViewMatrix) * normal;
  gl_Position = projectionMatrix * modelViewMatrix * vec4(position, 1.0);
}
