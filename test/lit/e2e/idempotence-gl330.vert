// A GL 330 shader converted twice (loose-uniform eye parameters) is left as it is the second time.
// RUN: %stereoshift --verify %s -o %t.1.vert
// RUN: %stereoshift --verify %t.1.vert -o %t.2.vert --report %t.json 2>&1 | FileCheck %s
// RUN: cmp %t.1.vert %t.2.vert
// RUN: FileCheck %s --check-prefix=REPORT --input-file %t.json
// CHECK: note: shader already carries stereo eye parameters ('eyeSign'); left as it is, never shifted twice
// REPORT: "classification": "already-stereo",
// REPORT: "output": "copied",
#version 330
uniform mat4 uMVP;
in vec3 aPosition;
void main() {
  gl_Position = uMVP * vec4(aPosition, 1.0);
}
