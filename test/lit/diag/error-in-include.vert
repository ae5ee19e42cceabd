// An error inside an included file is reported at the included file's own line:col.
// RUN: %not %stereoshift -I %S/Inputs/include %s -o %t.out 2>&1 | FileCheck %s
// RUN: test ! -e %t.out
// CHECK: {{.*}}Inputs/include/broken.glsl:2:14: error: 'notDeclared' : undeclared identifier
// CHECK: {{^[0-9]+}} errors generated.
#version 450
#extension GL_GOOGLE_include_directive : require
#include "broken.glsl"
void main() {
  gl_Position = vec4(helper(1.0));
}
