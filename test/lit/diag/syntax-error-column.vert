// The column of a syntax error is the column of the unexpected token (`2.0`, column 26), as in
// clang/DXC diagnostics.
// XFAIL: *
// BUG: syntax errors always get the column of the line's first non-blank character (here 3): glslang reports no token for them and the tool falls back to the indentation.
// RUN: %not %stereoshift %s -o %t.out 2>&1 | FileCheck %s
#version 450
void main() {
  gl_Position = vec4(1.0 2.0);
// CHECK: syntax-error-column.vert:[[@LINE-1]]:26: error: syntax error, unexpected FLOATCONSTANT
}
