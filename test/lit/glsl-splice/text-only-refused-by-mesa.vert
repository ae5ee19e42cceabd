#version 150
#extension GL_ARB_shader_texture_image_samples : require
// A shader every compiler refuses (a function nobody declares) in a shader whose #extension says
// it may lean on what glslang reads more narrowly than a driver: glslang's refusal could be its own
// gap, so Mesa's GLSL compiler is asked, and it refuses too. The text-only route is not taken: the
// user sees Mesa's errors at the file's line and column, exit 1, nothing written (before, the shift
// was spliced from the text and the conversion said yes).
// RUN: %not %stereoshift %s -o %t.vert --report %t.json 2>&1 | FileCheck %s
// RUN: %not test -e %t.vert
// RUN: FileCheck %s --check-prefix=REPORT < %t.json
// CHECK: text-only-refused-by-mesa.vert:28:{{[0-9]+}}: error: Mesa: no function with name 'textureSamplesUndeclared'
// CHECK: note: glslang refuses this shader too; the text-only route is taken only where Mesa's GLSL compiler ({{.*}}Mesa{{.*}}) compiles it
// CHECK: errors generated.
// REPORT: "mesa": {
// REPORT: "original": "refused"
//
// Without Mesa (no libEGL), the route is refused with what to install; --unchecked-text-route takes it.
// RUN: env STEREOSHIFT_EGL_LIBRARY=none %not %stereoshift %s -o %t.none.vert 2>&1 | FileCheck %s --check-prefix=NONE
// RUN: env STEREOSHIFT_EGL_LIBRARY=none %stereoshift %s --unchecked-text-route -o %t.unchecked.vert 2>&1 | FileCheck %s --check-prefix=UNCHECKED
// NONE: error: {{.*}}textureSamplesUndeclared
// NONE: note: the text-only route is taken only where Mesa's GLSL compiler compiles the shader, and none could be asked (no libEGL (STEREOSHIFT_EGL_LIBRARY=none)): install libegl1, libegl-mesa0 and libgl1-mesa-dri where Mesa is missing, or pass --unchecked-text-route to take it unchecked
// UNCHECKED: warning: no GLSL compiler checked this shader, which glslang refuses (no libEGL (STEREOSHIFT_EGL_LIBRARY=none)): the text-only route is taken unchecked (--unchecked-text-route)
uniform sampler2DMS depthSamples;
in vec4 position;
out float sampleCount;
void main()
{
    sampleCount = float(textureSamplesUndeclared(depthSamples));
    gl_Position = position * 2.0;
}
