#version 130
#extension GL_ARB_shader_bit_encoding : require
// GLSL 130 that leans on an extension glslang does not know at 130 (floatBitsToInt from
// GL_ARB_shader_bit_encoding): the analysis reads it through the legacy translation, but glslang's
// re-compile of the spliced output at 130 fails, as glslang fails on the original as written. That
// refusal is glslang's gap, not the output's: Mesa's GLSL compiler compiles the original and the
// output, so the splice is written, with a note and "mesa" in the report (before: an error). The
// output runs right (verify on lavapipe). Where glslang takes the original at the check, its word on
// the output stands (a broken output stays an error).
// RUN: %stereoshift %s -o %t.vert --report %t.json 2>&1 | FileCheck %s --check-prefix=NOTE
// RUN: %rmchecks %t.vert | FileCheck %s
// RUN: FileCheck %s --check-prefix=REPORT < %t.json
// RUN: %stereoshift verify %s | FileCheck %s --check-prefix=VERIFY
// NOTE: note: glslang does not take the output ('floatBitsToInt' : no matching overloaded function found), nor the original as written; Mesa's GLSL compiler compiles both
// CHECK: #version 130
// CHECK: gl_Position.x = gl_Position.x + (eyeSign * separation) * (gl_Position.w - convergence);
// REPORT: "mesa": {
// REPORT: "original": "compiled"
// REPORT: "output": "compiled"
// VERIFY: mono identity (eyeSign 0):   bit-exact
// VERIFY: verified
//
// Without Mesa, glslang's refusal of the output stands.
// RUN: env STEREOSHIFT_EGL_LIBRARY=none %not %stereoshift %s -o %t.none.vert 2>&1 | FileCheck %s --check-prefix=NONE
// NONE: error: the emitted shader does not compile at its original version
in vec4 position;
uniform mat4 mvp;
void main()
{
    gl_Position = mvp * position + vec4(intBitsToFloat(floatBitsToInt(0.0)));
}
