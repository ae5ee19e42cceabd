#version 120
// An output that is an exact copy of the clip position (a screen-space effect's varying) gets the
// shifted value after the shift; one derived from it cannot be carried by the text route and is
// said as a warning, never silently lost.
// RUN: %stereoshift %s -o %t.vert --report %t.json 2> %t.err
// RUN: %rmchecks %t.vert | FileCheck %s
// RUN: FileCheck %s --check-prefix=WARN --input-file %t.err
// RUN: glslangValidator -S vert %t.vert
// CHECK:      gl_Position.x = gl_Position.x
// CHECK:      {{^}}    vClip = gl_Position;
// CHECK-NEXT: {{^}}}
// WARN: warning: the legacy GLSL text route cannot carry the halo fix of output 'vScreen'
attribute vec3 position;
uniform mat4 mvp;
varying vec4 vClip;
varying vec2 vScreen;
void main() {
    gl_Position = mvp * vec4(position, 1.0);
    vClip = gl_Position;
    vScreen = gl_Position.xy / gl_Position.w;
}
