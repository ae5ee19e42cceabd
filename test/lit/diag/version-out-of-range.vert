#version 2147483648
// A #version number past int is refused with a clear error at the number (it used to throw
// std::out_of_range out of the version scan).
// RUN: %not %stereoshift %s -o %t.out 2>&1 | FileCheck %s
// RUN: test ! -e %t.out
// CHECK: version-out-of-range.vert:1:10: error: #version 2147483648 is not a GLSL version
// CHECK-NEXT: #version 2147483648
// CHECK-NEXT: {{^[[:blank:]]*\^$}}
// CHECK-NEXT: {{^}}1 error generated.
void main() {
  gl_Position = vec4(0.0);
}
