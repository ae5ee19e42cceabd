// A WebGL1 lesson's vertex shader: no #version, attribute/varying, no precision statement. It is
// GLSL's default 110 (nothing ES-only says otherwise); the output is the original text with `main`
// renamed and the shift appended, so attribute, varying and uniform names stay bindable by name.
// RUN: %stereoshift %s -o %t.vert --report %t.json
// RUN: %rmchecks %t.vert | FileCheck %s
// RUN: FileCheck %s --check-prefix=REPORT --input-file %t.json
// CHECK:      {{^}}attribute vec3 aVertexPosition;
// CHECK-NEXT: {{^}}attribute vec2 aTextureCoord;
// CHECK-NEXT: {{^}}uniform mat4 uMVMatrix;
// CHECK-NEXT: {{^}}uniform mat4 uPMatrix;
// CHECK-NEXT: {{^}}varying vec2 vTextureCoord;
// CHECK-NEXT: {{^}}void main_stereoshift_mono(void) {
// CHECK:      {{^}}uniform float eyeSign;
// CHECK-NEXT: {{^}}uniform float separation;
// CHECK-NEXT: {{^}}uniform float convergence;
// CHECK-NEXT: {{^}}void main()
// CHECK:      main_stereoshift_mono();
// CHECK-NEXT: if (eyeSign != 0.0 && abs(gl_Position.w - 1.0) > 9.99999975e-06 && abs(gl_Position.w) <= 3.40282347e+38)
// CHECK:      gl_Position.x = gl_Position.x + (eyeSign * separation) * (gl_Position.w - convergence);
// REPORT: "dialect": "110"
// REPORT: "dialect_reason": "no #version and nothing ES-only, so GLSL's default 110"
// REPORT: "route": "glsl-source-splice"
// REPORT: "verified": true
attribute vec3 aVertexPosition;
attribute vec2 aTextureCoord;
uniform mat4 uMVMatrix;
uniform mat4 uPMatrix;
varying vec2 vTextureCoord;
void main(void) {
    gl_Position = uPMatrix * uMVMatrix * vec4(aVertexPosition, 1.0);
    vTextureCoord = aTextureCoord;
}
