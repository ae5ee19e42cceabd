#version 150 compatibility
// A compatibility-profile geometry shader: `#version 150 compatibility`, the fixed-function matrix
// and gl_ClipVertex stay (a re-emission writes `#version 150`, a plain uniform for the matrix and a
// plain output for gl_ClipVertex). Each EmitVertex is wrapped with the shift of the vertex it
// emits; the line numbers do not move.
// RUN: %stereoshift %s -o - --report %t.json | %rmchecks | FileCheck %s
// RUN: FileCheck %s --check-prefix=REPORT < %t.json
// CHECK: #version 150 compatibility
// CHECK: /* ---- stereoshift ---- */ void stereoshift_shiftPosition(); /* ---- end stereoshift ---- */ void main()
// CHECK: gl_Position = gl_ModelViewProjectionMatrix * gl_in[i].gl_Position;
// CHECK-NEXT: gl_ClipVertex = gl_ModelViewMatrix * gl_in[i].gl_Position;
// CHECK-NEXT: { stereoshift_shiftPosition(); EmitVertex(); }
// CHECK: EndPrimitive();
// CHECK: void stereoshift_shiftPosition()
// CHECK-NEXT: {
// CHECK-NEXT:     if (eyeSign != 0.0 && abs(gl_Position.w - 1.0) > 9.99999975e-06 && !isinf(gl_Position.w))
// CHECK-NOT: uniform mat4 gl_ModelViewProjectionMatrix
// REPORT-DAG: "route": "glsl-source-splice"
// REPORT-DAG: "sites": 1
layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;
void main()
{
    for (int i = 0; i < 3; ++i) {
        gl_Position = gl_ModelViewProjectionMatrix * gl_in[i].gl_Position;
        gl_ClipVertex = gl_ModelViewMatrix * gl_in[i].gl_Position;
        EmitVertex();
    }
    EndPrimitive();
}
