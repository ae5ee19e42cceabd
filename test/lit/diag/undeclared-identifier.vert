// A semantic error points at its token: file:line:col of `undefinedThing`, the summary, exit != 0,
// no output file, and an existing output file is left as it was.
// RUN: rm -rf %t && mkdir %t && printf 'previous contents\n' > %t.orig
// RUN: %not %stereoshift %s -o %t/out.vert 2>&1 | FileCheck %s
// RUN: test ! -e %t/out.vert
// RUN: cp %t.orig %t/keep.vert
// RUN: %not %stereoshift %s -o %t/keep.vert
// RUN: cmp %t.orig %t/keep.vert
// RUN: ls -A %t | FileCheck %s --check-prefix=DIR
// DIR: {{^keep.vert$}}
// DIR-NOT: {{.}}
#version 450
void main() {
  gl_Position = vec4(undefinedThing, 1.0);
// CHECK: undeclared-identifier.vert:[[@LINE-1]]:22: error: 'undefinedThing' : undeclared identifier
// CHECK-NEXT: gl_Position = vec4(undefinedThing, 1.0);
// CHECK-NEXT: {{^[[:blank:]]*\^$}}
// CHECK-NEXT: {{^}}1 error generated.
}
