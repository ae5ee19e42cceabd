// The column of an error names the offending occurrence of its token, not the first occurrence of
// the same text on that line: the bad conversion is the third `=` (column 37).
// XFAIL: *
// BUG: the column is found by searching the line for glslang's token text, so it points at the first '=' of the line (column 11) instead of the one in error.
// RUN: %not %stereoshift %s -o %t.out 2>&1 | FileCheck %s
#version 450
void main() {
  float x = 1.0; float y = x; int z = y;
// CHECK: repeated-token-column.vert:[[@LINE-1]]:37: error: '=' : cannot convert from ' temp highp float' to ' temp highp int'
  gl_Position = vec4(x, y, float(z), 1.0);
}
