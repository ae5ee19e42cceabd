// A GLSL 1.10 vertex shader sizing the built-in texture-coordinate array itself, as the
// compatibility profile allows. The translation the analysis reads renames gl_TexCoord, and the
// shader's own declaration is the declaration: no second one beside it (before: "redeclaration of
// array with size", refused). The output keeps the shader's text (which glslang itself refuses:
// "identifiers starting with gl_ are reserved"; Mesa compiles it); checked by execution in
// test/harness/piglit/gl110-texcoord-array-sized.shader_test.
// RUN: %stereoshift %s -o %t.vert
// RUN: FileCheck %s < %t.vert
// RUN: %stereoshift %s --target glsl --target-version 330 -o - | FileCheck %s --check-prefix=GL330
// CHECK: {{^}}varying vec4 gl_TexCoord[3];
// CHECK: {{^}}void main_stereoshift_mono()
// GL330: #version 330
// GL330: out vec4 stereoshift_TexCoord[3];
// GL330-NOT: stereoshift_TexCoord[8]
varying vec4 gl_TexCoord[3];
uniform mat4 uModelViewProjection;
void main()
{
	gl_TexCoord[0] = gl_MultiTexCoord0;
	gl_TexCoord[2] = vec4(0.25);
	gl_Position = uModelViewProjection * gl_Vertex;
}
