#version 300 es
// Copies of the clip position that are not `name = gl_Position;` in the text: a struct varying's
// member and a plain output stored from the same value as the position (`pos` here). The IR proves
// each an exact copy of the one position value and the only store to its part, so the splice
// re-copies the shifted position to each, the struct varying kept as written (a re-emit flattened it
// into foo_a, which the next stage's `in Surface surf;` no longer links to).
// RUN: %stereoshift --verify %s -o %t.vert --report %t.json
// RUN: FileCheck %s --input-file %t.vert
// RUN: FileCheck %s --check-prefix=REPORT --input-file %t.json
// RUN: glslangValidator -S vert %t.vert
// CHECK:      {{^}}out Surface surf;
// CHECK:      {{^}}void main_stereoshift_mono()
// CHECK:      {{^}}    main_stereoshift_mono();
// CHECK:      {{^}}    surf.clip = gl_Position;
// CHECK-NEXT: {{^}}    vClip = gl_Position;
// REPORT: "route": "glsl-source-splice"
precision highp float;
struct Surface { vec4 clip; vec3 normal; };
in vec4 aPosition;
in vec3 aNormal;
uniform mat4 uMvp;
out Surface surf;
out vec4 vClip;
void main()
{
    vec4 pos = uMvp * aPosition;
    surf.clip = pos;
    surf.normal = aNormal;
    vClip = pos;
    gl_Position = pos;
}
