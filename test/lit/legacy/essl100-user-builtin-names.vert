// WebGL1 code that writes the ESSL 3 built-ins ESSL 100 lacks itself (inverse, transpose) converts:
// the analysis copy (ESSL 310) names them apart, the output keeps them and every call as written.
// RUN: %stereoshift %s -o %t.vert --report %t.json
// RUN: %rmchecks %t.vert | FileCheck %s
// RUN: FileCheck %s --check-prefix=REPORT --input-file %t.json
// RUN: glslangValidator -S vert %t.vert
// CHECK-NOT:  _stereoshift(
// CHECK:      {{^}}mat4 inverse(mat4 m)
// CHECK:      {{^}}mat3 transpose(mat3 m)
// CHECK:      {{^}}  vEye = (inverse(viewMatrix) * vec4(0.0, 0.0, 0.0, 1.0)).xyz;
// CHECK-NEXT: {{^}}  vNormal = transpose(mat3(viewMatrix[0].xyz, viewMatrix[1].xyz, viewMatrix[2].xyz)) * normal;
// CHECK:      {{^}}uniform float eyeSign;
// REPORT: "dialect": "100 es"
precision highp float;
attribute vec3 position;
attribute vec3 normal;
uniform mat4 viewMatrix;
uniform mat4 projectionMatrix;
varying vec3 vEye;
varying vec3 vNormal;
mat4 inverse(mat4 m) { return m; }
mat3 transpose(mat3 m)
{
  return mat3(m[0].x, m[1].x, m[2].x, m[0].y, m[1].y, m[2].y, m[0].z, m[1].z, m[2].z);
}
void main() {
  vEye = (inverse(viewMatrix) * vec4(0.0, 0.0, 0.0, 1.0)).xyz;
  vNormal = transpose(mat3(viewMatrix[0].xyz, viewMatrix[1].xyz, viewMatrix[2].xyz)) * normal;
  gl_Position = projectionMatrix * viewMatrix * vec4(position, 1.0);
}
