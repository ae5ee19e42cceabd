#version 300 es
// An ESSL 300 vertex shader with a struct varying: the output keeps `out Surface surf;` as written
// (a re-emission flattens it to surf_normal, surf_uv, which the fragment stage's `in Surface surf;`
// no longer links with), and the only edits are the renamed main and the appended block.
// RUN: %stereoshift %s -o - --report %t.json | %rmchecks | FileCheck %s
// RUN: FileCheck %s --check-prefix=REPORT < %t.json
// CHECK: struct Surface { vec3 normal; vec2 uv; };
// CHECK: out Surface surf;
// CHECK: void main_stereoshift_mono()
// CHECK-NEXT: {
// CHECK-NEXT:     surf.normal = aNormal;
// CHECK: // ---- stereoshift: stereo parameters and clip-space shift (injected) ----
// CHECK-NEXT: uniform float eyeSign;
// CHECK-NEXT: uniform float separation;
// CHECK-NEXT: uniform float convergence;
// CHECK-NEXT: void main()
// CHECK-NEXT: {
// CHECK-NEXT:     main_stereoshift_mono();
// CHECK-NEXT:     if (eyeSign != 0.0 && abs(gl_Position.w - 1.0) > 9.99999975e-06 && !isinf(gl_Position.w))
// CHECK-NEXT:     {
// CHECK-NEXT:         gl_Position.x = gl_Position.x + (eyeSign * separation) * (gl_Position.w - convergence);
// CHECK-NEXT:     }
// CHECK-NEXT: }
// CHECK-NEXT: // ---- end stereoshift ----
// CHECK-NOT: surf_normal
// REPORT: "route": "glsl-source-splice"
precision highp float;
struct Surface { vec3 normal; vec2 uv; };
uniform mat4 uModelViewProjection;
in vec4 aPosition;
in vec3 aNormal;
out Surface surf;
void main()
{
    surf.normal = aNormal;
    surf.uv = aPosition.xy * 0.5 + 0.5;
    gl_Position = uModelViewProjection * aPosition;
}
