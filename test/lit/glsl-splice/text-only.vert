#version 330
#extension GL_AMD_vertex_shader_layer : require
// What glslang cannot parse even lifted (here an extension it does not know, which Mesa's driver
// has: a vertex shader that picks its layer): Mesa's GLSL compiler compiles the original, so the
// shift is spliced from the text alone, with a warning that carries glslang's error and says what
// was not done, exit 0, and "analysis": "text-only" in the report; Mesa compiles the output too.
// --require-analysis makes it the error it was, and writes nothing.
// RUN: %stereoshift %s -o %t.vert --report %t.json 2>&1 | FileCheck %s --check-prefix=WARN
// RUN: %rmchecks %t.vert | FileCheck %s
// RUN: FileCheck %s --check-prefix=REPORT < %t.json
// RUN: %not %stereoshift --require-analysis %s -o %t.required.vert 2>&1 | FileCheck %s --check-prefix=REQUIRED
// RUN: %not test -e %t.required.vert
// WARN: warning: '#extension' : extension not supported: GL_AMD_vertex_shader_layer
// WARN: warning: glslang cannot analyse this shader: the clip-space shift was spliced from the text alone (not done: 2D proof
// WARN-NOT: error:
// CHECK: #version 330
// CHECK: void main_stereoshift_mono()
// CHECK: uniform float eyeSign;
// CHECK: gl_Position.x = gl_Position.x + (eyeSign * separation) * (gl_Position.w - convergence);
// REPORT-DAG: "analysis": "text-only"
// REPORT-DAG: "analysis_reason": "{{.*}}:2:1: error: '#extension' : extension not supported: GL_AMD_vertex_shader_layer"
// REPORT-DAG: "route": "glsl-text-only"
// REPORT-DAG: "eye_params": "loose uniforms"
// REPORT-DAG: "original": "compiled"
// REPORT-DAG: "output": "compiled"
// REQUIRED: error: '#extension' : extension not supported: GL_AMD_vertex_shader_layer
// REQUIRED: 2 errors generated.
in vec4 position;
uniform int layer;
void main()
{
    gl_Layer = layer;
    gl_Position = position * 2.0;
}
