#version 150
#extension GL_ARB_arrays_of_arrays : require
// GL_ARB_arrays_of_arrays under #version 150: drivers compile it; glslang does not know the
// extension by name ("extension not supported", an error under `require`) and takes arrays of
// arrays only from 430. The lifted copy raises the version to 430 and blanks the #extension line
// (core there; spaces, so offsets stay); the output is the original text plus the marked edits.
// Before, the shader fell back to the text-only shift.
// RUN: %stereoshift %s -o - --report %t.json | %rmchecks | FileCheck %s
// RUN: FileCheck %s --check-prefix=REPORT < %t.json
// CHECK: #version 150
// CHECK-NEXT: #extension GL_ARB_arrays_of_arrays : require
// CHECK: void main_stereoshift_mono()
// CHECK: // ---- stereoshift: stereo parameters and clip-space shift (injected) ----
// REPORT-DAG: "analysis": "lifted"
// REPORT-DAG: "lifted": "the analysis copy's #version 330 raised to 430 for GL_ARB_arrays_of_arrays"
// REPORT-DAG: "route": "glsl-source-splice"
// REPORT-DAG: "classification": "perspective"
in vec4 position;
in float boneWeight;
uniform mat4 viewProjection;
uniform float cascadeScale[2][3];
void main()
{
    gl_Position = viewProjection * position * (cascadeScale[1][2] * boneWeight);
}
