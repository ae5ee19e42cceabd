#version 410 core
// A tessellation-evaluation shader is spliced like a vertex shader (main renamed, the shifting
// main appended). A converted shader converted again is left as it is (copied), never shifted twice.
// RUN: %stereoshift %s -o %t.tese
// RUN: %rmchecks %t.tese | FileCheck %s
// RUN: %stereoshift %t.tese -o %t.twice.tese 2>&1 | FileCheck %s --check-prefix=TWICE
// RUN: cmp %t.tese %t.twice.tese
// CHECK: {{^}}#version 410 core
// CHECK: {{^}}layout(triangles, equal_spacing, ccw) in;
// CHECK-NEXT: {{^}}uniform mat4 mvp;
// CHECK-NEXT: {{^}}void main_stereoshift_mono()
// CHECK: {{^}}    gl_Position = mvp * p;
// CHECK-NEXT: {{^}}}
// CHECK-NEXT: {{^}}// ---- stereoshift: stereo parameters and clip-space shift (injected) ----
// CHECK-NEXT: {{^}}uniform float eyeSign;
// CHECK-NEXT: {{^}}uniform float separation;
// CHECK-NEXT: {{^}}uniform float convergence;
// CHECK-NEXT: {{^}}void main()
// CHECK-NEXT: {
// CHECK-NEXT:     main_stereoshift_mono();
// CHECK-NEXT: if (eyeSign != 0.0 && abs(gl_Position.w - 1.0) > 9.99999975e-06 && !isinf(gl_Position.w))
// CHECK-NEXT: {
// CHECK-NEXT: precise float stereoshift_x = gl_Position.x + (eyeSign * separation) * (gl_Position.w - convergence);
// CHECK-NEXT: gl_Position.x = stereoshift_x;
// CHECK-NEXT: }
// CHECK-NEXT: }
// CHECK-NEXT: {{^}}// ---- end stereoshift ----
// TWICE: note: shader already carries stereo eye parameters ('eyeSign'); left as it is, never shifted twice
layout(triangles, equal_spacing, ccw) in;
uniform mat4 mvp;
void main()
{
    vec4 p = gl_TessCoord.x * gl_in[0].gl_Position + gl_TessCoord.y * gl_in[1].gl_Position +
             gl_TessCoord.z * gl_in[2].gl_Position;
    gl_Position = mvp * p;
}
