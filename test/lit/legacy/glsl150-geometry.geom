#version 150
// A GLSL 150 geometry shader comes back as its own text at version 150 (glsl-source-splice route):
// each EmitVertex() is wrapped with the shift of the vertex it emits, the helper's prototype goes
// before main, and the loose eye uniforms and the helper (no `precise` before GLSL 400) are appended.
// RUN: %stereoshift %s --verify -o - --report %t.json | %rmchecks | FileCheck %s
// RUN: FileCheck %s --check-prefix=REPORT --input-file %t.json
// CHECK: {{^}}#version 150{{$}}
// CHECK: {{^}}layout(triangles) in;
// CHECK-NEXT: layout(triangle_strip, max_vertices = 3) out;
// CHECK-NEXT: {{^}}uniform mat4 viewProjection;
// CHECK-NEXT: {{^}}in vec3 worldPosition[];
// CHECK-NEXT: {{^}}/* ---- stereoshift ---- */ void stereoshift_shiftPosition(); /* ---- end stereoshift ---- */ void main() {
// CHECK-NEXT: for (int i = 0; i < 3; ++i) {
// CHECK-NEXT: gl_Position = viewProjection * vec4(worldPosition[i], 1.0);
// CHECK-NEXT: { stereoshift_shiftPosition(); EmitVertex(); }
// CHECK-NEXT: }
// CHECK-NEXT: EndPrimitive();
// CHECK-NEXT: }
// CHECK-NEXT: // ---- stereoshift: stereo parameters and clip-space shift (injected) ----
// CHECK-NEXT: {{^}}uniform float eyeSign;
// CHECK-NEXT: {{^}}uniform float separation;
// CHECK-NEXT: {{^}}uniform float convergence;
// CHECK-NEXT: {{^}}void stereoshift_shiftPosition()
// CHECK-NEXT: {
// CHECK-NEXT: if (eyeSign != 0.0 && abs(gl_Position.w - 1.0) > 9.99999975e-06 && !isinf(gl_Position.w))
// CHECK-NEXT: {
// CHECK-NEXT: {{^ *}}gl_Position.x = gl_Position.x + (eyeSign * separation) * (gl_Position.w - convergence);
// CHECK-NEXT: }
// CHECK-NEXT: }
// CHECK-NEXT: // ---- end stereoshift ----
// CHECK-NOT: precise
// CHECK-NOT: EmitVertex
// REPORT: "route": "glsl-source-splice",
layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;
uniform mat4 viewProjection;
in vec3 worldPosition[];
void main() {
    for (int i = 0; i < 3; ++i) {
        gl_Position = viewProjection * vec4(worldPosition[i], 1.0);
        EmitVertex();
    }
    EndPrimitive();
}
