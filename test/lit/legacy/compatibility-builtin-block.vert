#version 150 compatibility
// A compatibility shader that redeclares its output block with compatibility members (the colour
// and texture coordinates it writes): the analysis copy leaves the redeclaration out (its members
// are the translation's own declarations, gl_Position a core built-in without it), so the shader is
// analysed, not spliced from the text alone; the output keeps the block as written, and Mesa's GLSL
// compiler (which takes the redeclaration at 150, where glslang does not) compiles it.
// RUN: %stereoshift %s -o %t.vert --report %t.json 2>&1 | FileCheck %s --check-prefix=NOTE
// RUN: %rmchecks %t.vert | FileCheck %s
// RUN: FileCheck %s --check-prefix=REPORT --input-file %t.json
// RUN: %stereoshift verify %s | FileCheck %s --check-prefix=VERIFY
// NOTE-NOT: warning
// NOTE: note: glslang does not take the output ({{.*}}), nor the original as written; Mesa's GLSL compiler compiles both
// CHECK:      {{^}}out gl_PerVertex { vec4 gl_Position; vec4 gl_FrontColor; vec4 gl_TexCoord[2]; };
// CHECK:      {{^}}void main_stereoshift_mono()
// CHECK:      gl_Position.x = gl_Position.x + (eyeSign * separation) * (gl_Position.w - convergence);
// REPORT: "classification": "perspective"
// REPORT: "route": "glsl-source-splice"
// VERIFY: verified
out gl_PerVertex { vec4 gl_Position; vec4 gl_FrontColor; vec4 gl_TexCoord[2]; };
void main()
{
    gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex;
    gl_FrontColor = gl_Color;
    gl_TexCoord[0] = gl_MultiTexCoord0;
}
