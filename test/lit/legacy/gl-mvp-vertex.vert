#version 110
// `gl_ModelViewProjectionMatrix * gl_Vertex`: the compatibility matrix and attribute are read as a
// uniform and an input in the analysis; the shift goes after the user's main.
// RUN: %stereoshift %s -o %t.vert --report %t.json
// RUN: %rmchecks %t.vert | FileCheck %s
// RUN: FileCheck %s --check-prefix=REPORT --input-file %t.json
// RUN: glslangValidator -S vert %t.vert
// CHECK: {{^}}    gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex;
// CHECK: {{^}}uniform float eyeSign;
// REPORT: "classification": "perspective"
// REPORT: "dialect": "110"
void main()
{
    gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex;
}
