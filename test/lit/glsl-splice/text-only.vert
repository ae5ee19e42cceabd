#version 150
#extension GL_ARB_shader_texture_image_samples : require
// What glslang cannot parse even lifted (here a function glslang does not know in a shader whose
// #extension says it may lean on what glslang reads more narrowly than a driver): the shift is spliced from the text alone,
// with a warning that carries glslang's error and says what was not done, exit 0, and
// "analysis": "text-only" in the report. --require-analysis makes it the error it was, and writes
// nothing.
// RUN: %stereoshift %s -o %t.vert --report %t.json 2>&1 | FileCheck %s --check-prefix=WARN
// RUN: %rmchecks %t.vert | FileCheck %s
// RUN: FileCheck %s --check-prefix=REPORT < %t.json
// RUN: %not %stereoshift --require-analysis %s -o %t.required.vert 2>&1 | FileCheck %s --check-prefix=REQUIRED
// RUN: %not test -e %t.required.vert
// WARN: warning: {{.*}}textureSamplesUndeclared
// WARN: warning: glslang cannot analyse this shader: the clip-space shift was spliced from the text alone (not done: 2D proof
// WARN-NOT: error:
// CHECK: #version 150
// CHECK: void main_stereoshift_mono()
// CHECK: uniform float eyeSign;
// CHECK: gl_Position.x = gl_Position.x + (eyeSign * separation) * (gl_Position.w - convergence);
// REPORT-DAG: "analysis": "text-only"
// REPORT-DAG: "analysis_reason": "{{.*}}:31:25: error: {{.*}}textureSamplesUndeclared{{.*}}"
// REPORT-DAG: "route": "glsl-text-only"
// REPORT-DAG: "eye_params": "loose uniforms"
// REQUIRED: error: {{.*}}textureSamplesUndeclared
// REQUIRED: 1 error generated.
uniform sampler2DMS depthSamples;
in vec4 position;
out float sampleCount;
void main()
{
    sampleCount = float(textureSamplesUndeclared(depthSamples));
    gl_Position = position * 2.0;
}
