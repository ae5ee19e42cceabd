// A missing #include: the error names the directive's line:col, the summary follows, exit != 0,
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
#extension GL_GOOGLE_include_directive : require
#include "does-not-exist.glsl"
// CHECK: missing-include.vert:[[@LINE-1]]:1: error: '#include' : Could not process include directive for header name: does-not-exist.glsl
// CHECK-NEXT: #include "does-not-exist.glsl"
// CHECK-NEXT: {{^[[:blank:]]*\^$}}
// CHECK-NEXT: {{^}}1 error generated.
void main() {
  gl_Position = vec4(1.0);
}
