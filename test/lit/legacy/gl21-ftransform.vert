#version 120
// A GL 2.1 tutorial: ftransform() and compatibility colours. The analysis reads ftransform() as
// (gl_ModelViewProjectionMatrix * gl_Vertex); the output is the original text, `ftransform()` kept.
// RUN: %stereoshift %s -o %t.vert --report %t.json
// RUN: %rmchecks %t.vert | FileCheck %s
// RUN: FileCheck %s --check-prefix=REPORT --input-file %t.json
// RUN: glslangValidator -S vert %t.vert
// CHECK:     {{^}}void main_stereoshift_mono() {
// CHECK-NEXT: gl_FrontColor = gl_Color;
// CHECK-NEXT: gl_Position = ftransform();
// CHECK:     gl_Position.x = gl_Position.x + (eyeSign * separation) * (gl_Position.w - convergence);
// CHECK-NOT: stereoshift_Vertex
// REPORT: "classification": "perspective"
// REPORT: "dialect": "120"
void main() {
    gl_FrontColor = gl_Color;
    gl_Position = ftransform();
}
