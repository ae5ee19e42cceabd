#version 330
#extension GL_ARB_gpu_shader5 : require
// GL_ARB_gpu_shader5's built-ins under #version 330: drivers compile them, glslang knows them only
// from 400. The analysis runs on a lifted copy (#version raised to 400 for the extension); the
// output is the original text, #version 330 and all, plus the splice's marked edits.
// RUN: %stereoshift %s -o - --report %t.json | %rmchecks | FileCheck %s
// RUN: FileCheck %s --check-prefix=REPORT < %t.json
// CHECK: #version 330
// CHECK-NEXT: #extension GL_ARB_gpu_shader5 : require
// CHECK: void main_stereoshift_mono()
// CHECK: umulExtended(seed.x, seed.y, hi, lo);
// CHECK: // ---- stereoshift: stereo parameters and clip-space shift (injected) ----
// CHECK-NOT: #version 400
// REPORT-DAG: "analysis": "lifted"
// REPORT-DAG: "lifted": "the analysis copy's #version 330 raised to 400 for GL_ARB_gpu_shader5"
// REPORT-DAG: "route": "glsl-source-splice"
// REPORT-DAG: "classification": "perspective"
in vec4 position;
in uvec2 seed;
uniform mat4 mvp;
out float jitter;
void main()
{
    uint hi, lo;
    umulExtended(seed.x, seed.y, hi, lo);
    jitter = float(findMSB(hi));
    gl_Position = mvp * position;
}
