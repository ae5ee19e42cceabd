#version 130
// GLSL 130 in/out: the output stays 130; the cutoff uses isinf, which 130 has.
// RUN: %stereoshift %s -o %t.vert --report %t.json
// RUN: %rmchecks %t.vert | FileCheck %s
// RUN: FileCheck %s --check-prefix=REPORT --input-file %t.json
// RUN: glslangValidator -S vert %t.vert
// CHECK: {{^}}#version 130
// CHECK: {{^}}in vec3 position;
// CHECK: !isinf(gl_Position.w)
// REPORT: "dialect": "130"
// REPORT: "verified": true
in vec3 position;
in vec3 normal;
out vec3 vNormal;
uniform mat4 modelView;
uniform mat4 projection;
void main() {
    vNormal = normal;
    gl_Position = projection * modelView * vec4(position, 1.0);
}
