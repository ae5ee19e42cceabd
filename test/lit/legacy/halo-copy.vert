#version 120
// An output that is an exact copy of the clip position (a screen-space effect's varying) gets the
// shifted value after the shift; one derived from it reads the position, in its one assignment,
// through stereoshift_shifted_position (the position as the shift leaves it). Re-compiled at 1.20.
// RUN: %stereoshift %s -o %t.vert --report %t.json 2> %t.err
// RUN: %rmchecks %t.vert | FileCheck %s
// RUN: FileCheck %s --check-prefix=WARN --allow-empty --input-file %t.err
// RUN: glslangValidator -S vert %t.vert
// WARN-NOT: cannot carry
// CHECK:      vScreen = stereoshift_shifted_position(gl_Position).xy / stereoshift_shifted_position(gl_Position).w;
// CHECK:      vec4 stereoshift_shifted_position(vec4 stereoshift_p)
// CHECK:      abs(stereoshift_p.w) <= 3.40282347e+38
// CHECK:      gl_Position.x = gl_Position.x
// CHECK:      {{^}}    vClip = gl_Position;
// CHECK-NEXT: {{^}}}
attribute vec3 position;
uniform mat4 mvp;
varying vec4 vClip;
varying vec2 vScreen;
void main() {
    gl_Position = mvp * vec4(position, 1.0);
    vClip = gl_Position;
    vScreen = gl_Position.xy / gl_Position.w;
}
