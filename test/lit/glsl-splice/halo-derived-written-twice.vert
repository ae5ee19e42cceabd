#version 330 core
// The changed/unchanged pair of halo-derived-output.vert: the refraction UVs are written twice (a
// fallback for points behind the camera), so the text has no one assignment that holds the value
// the analysis re-derived: the splice declines with the reason and SPIRV-Cross re-emits the IR's fix.
// RUN: %stereoshift --validate-each %s -o %t.vert 2>&1 | FileCheck %s --check-prefix=NOTE
// RUN: %rmchecks %t.vert | FileCheck %s
// NOTE: note: GLSL re-emitted by SPIRV-Cross instead of spliced into its own text: the halo pass changed the output 'vRefractUV', which is computed from the clip position in a way the text does not show (recomputed, or written more than once), and only the IR carries that
// CHECK-NOT: stereoshift_shifted_position
// CHECK: vRefractUV =
uniform mat4 uViewProj;
in vec3 aPos;
out vec2 vRefractUV;

void main()
{
    vec4 clip = uViewProj * vec4(aPos, 1.0);
    gl_Position = clip;
    vRefractUV = (clip.xy / clip.w) * 0.5 + 0.5;
    if (clip.w <= 0.0)
        vRefractUV = vec2(0.5);
}
