#version 100
// ESSL 100 (attribute/varying) is no longer refused: it converts in its own dialect (test/lit/legacy/).
// RUN: %stereoshift %s -o %t.out 2>&1 | count 0
// RUN: %rmchecks %t.out | FileCheck %s
// CHECK: {{^}}attribute vec3 aPosition;
// CHECK: {{^}}void main_stereoshift_mono() {
attribute vec3 aPosition;
uniform mat4 uMVP;
void main() {
  gl_Position = uMVP * vec4(aPosition, 1.0);
}
