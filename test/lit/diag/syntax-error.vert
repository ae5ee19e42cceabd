// A syntax error: file:line:col: error:, the closing summary, exit != 0, no output file (not even a
// temporary one left behind), and an existing output file keeps its contents.
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
  gl_Position = vec4(1.0 2.0);
// CHECK: syntax-error.vert:[[@LINE-1]]:{{[0-9]+}}: error: syntax error, unexpected FLOATCONSTANT, expecting RIGHT_PAREN or COMMA
// CHECK-NEXT: gl_Position = vec4(1.0 2.0);
// CHECK-NEXT: {{^[[:blank:]]*\^$}}
// CHECK-NEXT: {{^}}1 error generated.
}
