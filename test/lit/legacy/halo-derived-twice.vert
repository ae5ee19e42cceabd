#version 120
// The unchanged pair of halo-copy.vert: the derived output is written twice (clamped when behind the
// camera), so its one assignment is not in the text: the legacy text route says it leaves that halo
// fix out (a warning and the report's not_carried), never silently.
// RUN: %stereoshift %s -o %t.vert --report %t.json 2> %t.err
// RUN: FileCheck %s --check-prefix=WARN --input-file %t.err
// RUN: FileCheck %s --check-prefix=REPORT --input-file %t.json
// RUN: %rmchecks %t.vert | FileCheck %s
// WARN: warning: the legacy GLSL text route cannot carry the halo fix of output 'vScreen'
// REPORT: "not_carried": [
// REPORT-NEXT: "the halo fix of output 'vScreen' (derived from the clip position, not a plain copy)"
// CHECK-NOT: stereoshift_shifted_position
// CHECK: vClip = gl_Position;
attribute vec3 position;
uniform mat4 mvp;
varying vec4 vClip;
varying vec2 vScreen;
void main() {
    gl_Position = mvp * vec4(position, 1.0);
    vClip = gl_Position;
    vScreen = gl_Position.xy / gl_Position.w;
    if (gl_Position.w < 0.0)
        vScreen = vec2(0.0);
}
