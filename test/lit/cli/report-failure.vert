// A failed conversion still writes its report, marked "ok": false.
// RUN: %not %stereoshift %s -o %t.out --report %t.json
// RUN: test ! -e %t.out
// RUN: FileCheck %s --input-file %t.json
#version 450
void main() {
  gl_Position = vec4(undefinedThing);
}
// CHECK: {
// CHECK-NEXT: "file": "{{.*}}report-failure.vert",
// CHECK-NEXT: "ok": false
// CHECK-NEXT: }
