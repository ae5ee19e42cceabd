#version 330
// A line continuation (a backslash at a line's end), which glslang refuses before GLSL 420 and
// drivers accept: the analysis runs on a copy with it joined, the output keeps it as written.
// RUN: %stereoshift %s -o - --report %t.json | %rmchecks | FileCheck %s
// RUN: FileCheck %s --check-prefix=REPORT < %t.json
// CHECK: gl_Position = mvp * \
// CHECK-NEXT: {{^}}        position;
// CHECK: main_stereoshift_mono();
// REPORT: "lifted": "line continuations joined"
uniform mat4 mvp;
in vec4 position;
void main()
{
    gl_Position = mvp * \
        position;
}
