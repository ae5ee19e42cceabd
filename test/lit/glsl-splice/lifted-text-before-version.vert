// An ESSL shader with comments and a blank line before #version (ESSL wants it first; glslang
// refuses it, drivers differ): the analysis runs on a copy with #version moved to the top and the
// lines before it blank, so every later line keeps its number; the output keeps the text as written.
// RUN: %stereoshift %s -o %t.vert --report %t.json
// RUN: %rmchecks %t.vert | FileCheck %s
// RUN: FileCheck %s --check-prefix=REPORT < %t.json
// CHECK: {{^}}// An ESSL shader with comments
// CHECK: {{^}}#version 300 es
// CHECK: void main_stereoshift_mono()
// CHECK: uniform float eyeSign;
// REPORT-DAG: "lifted": "the text before #version moved after it"
// REPORT-DAG: "route": "glsl-source-splice"
// REPORT-DAG: "classification": "perspective"

#version 300 es
uniform mat4 uMVP;
in vec4 aPosition;
void main()
{
    gl_Position = uMVP * aPosition;
}
