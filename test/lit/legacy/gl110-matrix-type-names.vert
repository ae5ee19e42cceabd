#version 110
// GLSL 1.20 made mat2x2 ... mat4x4 keywords; in a GLSL 110 text they are plain names. The GLSL 330
// analysis translation names them apart, the output keeps them as written. (Before: "syntax error,
// unexpected MAT4X2".)
// RUN: %stereoshift %s -o %t.vert
// RUN: %rmchecks %t.vert | FileCheck %s
// CHECK:      {{^}}uniform float mat4x2;
// CHECK:      {{^}}    vTint = vec4(mat4x2);
// CHECK:      {{^}}uniform float eyeSign;
uniform float mat4x2;
varying vec4 vTint;
void main()
{
    vTint = vec4(mat4x2);
    gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex;
}
