#version 120
// gl_TexCoord[0] and gl_MultiTexCoord0 with gl_TextureMatrix: translated for the analysis, kept in
// the output; across languages they become declared variables (stereoshift_TexCoord).
// RUN: %stereoshift %s -o %t.vert
// RUN: %rmchecks %t.vert | FileCheck %s
// RUN: glslangValidator -S vert %t.vert
// RUN: %stereoshift %s --target glsl --target-version 330 --verify -o - | FileCheck %s --check-prefix=GL330
// CHECK: {{^}}    gl_TexCoord[0] = gl_TextureMatrix[0] * gl_MultiTexCoord0;
// CHECK: {{^}}void main()
// GL330: #version 330
// GL330-DAG: out vec4 stereoshift_TexCoord[8];
// GL330-DAG: in vec4 stereoshift_MultiTexCoord0;
// GL330-DAG: uniform mat4 stereoshift_TextureMatrix[8];
uniform mat4 modelViewProjection;
void main() {
    gl_TexCoord[0] = gl_TextureMatrix[0] * gl_MultiTexCoord0;
    gl_Position = modelViewProjection * gl_Vertex;
}
