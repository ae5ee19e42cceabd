#version 410 core
// A tessellation-evaluation shader is spliced like a vertex shader (main renamed, the shifting
// main appended). A converted shader converted again is left as it is (copied), never shifted twice.
// RUN: %stereoshift %s -o %t.tese
// RUN: FileCheck %s < %t.tese
// RUN: %stereoshift %t.tese -o %t.twice.tese 2>&1 | FileCheck %s --check-prefix=TWICE
// RUN: cmp %t.tese %t.twice.tese
// CHECK: layout(triangles, equal_spacing, ccw) in;
// CHECK: void main_stereoshift_mono()
// CHECK: void main()
// CHECK-NEXT: {
// CHECK-NEXT:     main_stereoshift_mono();
// TWICE: note: shader already carries stereo eye parameters ('eyeSign'); left as it is, never shifted twice
layout(triangles, equal_spacing, ccw) in;
uniform mat4 mvp;
void main()
{
    vec4 p = gl_TessCoord.x * gl_in[0].gl_Position + gl_TessCoord.y * gl_in[1].gl_Position +
             gl_TessCoord.z * gl_in[2].gl_Position;
    gl_Position = mvp * p;
}
