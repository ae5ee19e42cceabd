#version 140
// GLSL 140 with a uniform block: the output stays 140; the eye parameters are loose uniforms (the
// legacy text route's convention), not a second block.
// RUN: %stereoshift %s -o %t.vert --report %t.json
// RUN: %rmchecks %t.vert | FileCheck %s
// RUN: FileCheck %s --check-prefix=REPORT --input-file %t.json
// RUN: glslangValidator -S vert %t.vert
// CHECK: {{^}}uniform Transforms { mat4 mvp; };
// CHECK: {{^}}uniform float eyeSign;
// CHECK-NOT: StereoParams
// REPORT: "dialect": "140"
// REPORT: "declared": "loose uniforms"
in vec4 vertex;
uniform Transforms { mat4 mvp; };
void main() {
    gl_Position = mvp * vertex;
}
