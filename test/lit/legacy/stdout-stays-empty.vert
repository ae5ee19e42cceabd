#version 110
// glslang asked for GLSL 110/120 with a SPIR-V client fails its own built-ins and prints ~3,700
// lines of them to standard output. stereoshift never asks it that: standard output stays empty,
// for a good shader and for a broken one (whose error points at the user's line).
// RUN: %stereoshift %s -o %t.vert > %t.stdout
// RUN: test ! -s %t.stdout
// RUN: sed 's/#version 110/#version 120/; s/vec4(1.0)/undefinedName/' %s > %t.bad.vert
// RUN: %not %stereoshift %t.bad.vert -o %t.bad.out > %t.bad.stdout 2> %t.bad.stderr
// RUN: test ! -s %t.bad.stdout
// RUN: test ! -e %t.bad.out
// RUN: FileCheck %s --input-file %t.bad.stderr
// CHECK: bad.vert:14:31: error: 'undefinedName' : undeclared identifier
void main() {
    gl_Position = gl_Vertex + vec4(1.0);
}
