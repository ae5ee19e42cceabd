// A failed conversion still writes its report, marked "ok": false, with the errors as printed and
// the language it was parsed as and why (often the reason it failed).
// RUN: %not %stereoshift %s -o %t.out --report %t.json
// RUN: test ! -e %t.out
// RUN: FileCheck %s --input-file %t.json
#version 450
void main() {
  gl_Position = vec4(undefinedThing);
}
// CHECK: {
// CHECK-NEXT: "errors": [
// CHECK-NEXT: "{{.*}}report-failure.vert:8:{{[0-9]+}}: error: 'undefinedThing' : undeclared identifier"
// CHECK-NEXT: ],
// CHECK-NEXT: "file": "{{.*}}report-failure.vert",
// CHECK-NEXT: "language": "glsl",
// CHECK-NEXT: "language_reason": "#version directive",
// CHECK-NEXT: "language_source": "content",
// CHECK-NEXT: "ok": false
// CHECK-NEXT: }
