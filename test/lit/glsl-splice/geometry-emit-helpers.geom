#version 400
// Emits in a helper function, under #ifdef branches and through EmitStreamVertex: each emit
// statement is wrapped, each function that emits gets the helper's prototype first (both branches
// of the #if, each defining its own), and unbraced `if (...) EmitVertex();` stays one statement.
// RUN: %stereoshift %s -o - --report %t.json | %rmchecks | FileCheck %s
// RUN: FileCheck %s --check-prefix=REPORT < %t.json
// CHECK: /* ---- stereoshift ---- */ void stereoshift_shiftPosition(); /* ---- end stereoshift ---- */ void emitCorner(vec4 p)
// CHECK-NEXT: {
// CHECK-NEXT:     gl_Position = p;
// CHECK-NEXT:     if (p.w > 0.0) { stereoshift_shiftPosition(); EmitStreamVertex(0); }
// CHECK: #ifdef WIDE_LINES
// CHECK-NEXT: /* ---- stereoshift ---- */ void stereoshift_shiftPosition(); /* ---- end stereoshift ---- */ void main()
// CHECK: #else
// CHECK-NEXT: /* ---- stereoshift ---- */ void stereoshift_shiftPosition(); /* ---- end stereoshift ---- */ void main()
// CHECK: { stereoshift_shiftPosition(); EmitVertex(); }
// CHECK: void stereoshift_shiftPosition()
// REPORT: "sites": 3
layout(lines) in;
layout(line_strip, max_vertices = 4) out;
uniform mat4 viewProjection;

void emitCorner(vec4 p)
{
    gl_Position = p;
    if (p.w > 0.0) EmitStreamVertex(0);
}

#ifdef WIDE_LINES
void main()
{
    emitCorner(viewProjection * gl_in[0].gl_Position);
    gl_Position = viewProjection * gl_in[1].gl_Position;
    EmitVertex();
    EndPrimitive();
}
#else
void main()
{
    gl_Position = viewProjection * gl_in[0].gl_Position;
    EmitVertex();
    emitCorner(viewProjection * gl_in[1].gl_Position);
    EndPrimitive();
}
#endif
