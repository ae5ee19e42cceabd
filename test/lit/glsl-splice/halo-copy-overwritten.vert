#version 300 es
// A copy of the clip position whose output part is written again (here, in a branch) cannot be
// re-copied at the end: the text would lose the other value. The splice declines and the re-emit,
// which carries the IR's per-store shift, writes the stage, with a note saying why.
// RUN: %stereoshift --verify %s -o %t.vert 2>%t.notes
// RUN: FileCheck %s --input-file %t.notes
// CHECK: note: GLSL re-emitted by SPIRV-Cross instead of spliced into its own text: the halo copy 'surf' of the clip position is not a plain `surf = gl_Position;` in the text
precision highp float;
struct Surface { vec4 clip; };
in vec4 aPosition;
uniform mat4 uMvp;
uniform bool uFlat;
out Surface surf;
void main()
{
    vec4 pos = uMvp * aPosition;
    surf.clip = pos;
    if (uFlat) surf.clip = vec4(0.0);
    gl_Position = pos;
}
