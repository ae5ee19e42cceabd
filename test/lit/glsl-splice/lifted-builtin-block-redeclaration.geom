#version 150
// A GLSL 150 geometry shader that redeclares the built-in blocks (`in gl_PerVertex {...} gl_in[];`,
// `out gl_PerVertex {...};`) with only the members it uses: drivers compile it, glslang takes
// built-in block redeclarations from GLSL 410 on. The lifted copy is raised to 410 for the
// analysis; the output is the original text, both redeclarations as written, plus the wrapped
// emits. Before, the conversion stopped at "built-in block redeclaration".
// RUN: %stereoshift %s -o - --report %t.json | %rmchecks | FileCheck %s
// RUN: FileCheck %s --check-prefix=REPORT < %t.json
// CHECK: #version 150
// CHECK: in gl_PerVertex { vec4 gl_Position; } gl_in[];
// CHECK-NEXT: out gl_PerVertex { vec4 gl_Position; };
// CHECK: { stereoshift_shiftPosition(); EmitVertex(); }
// REPORT-DAG: "analysis": "lifted"
// REPORT-DAG: "lifted": "the analysis copy's #version 330 raised to 410 for a gl_PerVertex redeclaration"
// REPORT-DAG: "route": "glsl-source-splice"
layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;
in gl_PerVertex { vec4 gl_Position; } gl_in[];
out gl_PerVertex { vec4 gl_Position; };
uniform mat4 viewProjection;
void main()
{
    for (int i = 0; i < 3; i++) {
        gl_Position = viewProjection * gl_in[i].gl_Position;
        EmitVertex();
    }
    EndPrimitive();
}
