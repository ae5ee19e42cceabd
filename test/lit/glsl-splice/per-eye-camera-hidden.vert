// per-eye-view where the text is not plain enough to be sure which reads are the camera's: a
// parameter of a helper hides the camera's name, so a wrap by name could move the wrong value.
// The splice declines with the reason and SPIRV-Cross re-emits the IR fix (which knows each load).
// RUN: %stereoshift --validate-each %s -o %t.vert 2>&1 | FileCheck %s --check-prefix=NOTE
// RUN: %rmchecks %t.vert | FileCheck %s
// NOTE: note: GLSL re-emitted by SPIRV-Cross instead of spliced into its own text: a local or parameter named 'uEyePos' hides the camera 'uEyePos'
// CHECK-NOT: stereoshift_eye_
// CHECK: inverse(uViewProj)
#version 330
uniform mat4 uModel;
uniform mat4 uViewProj;
uniform vec3 uEyePos;
in vec3 aPosition;
in vec3 aNormal;
in vec4 aTangent;
out vec3 vView;

vec3 fromTo(vec3 uEyePos, vec3 p) { return uEyePos - p; }

void main()
{
    vec4 world = uModel * vec4(aPosition, 1.0);
    vec3 n = normalize(mat3(uModel) * aNormal);
    vec3 t = normalize(mat3(uModel) * aTangent.xyz);
    mat3 tbn = transpose(mat3(t, cross(n, t) * aTangent.w, n));
    vView = tbn * fromTo(uEyePos, world.xyz);
    gl_Position = uViewProj * world;
}
