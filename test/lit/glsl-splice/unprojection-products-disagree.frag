#version 330
// The text multiplies the inverse view-projection twice, once to rebuild the pixel's position from
// depth (fixed) and once for a constant point (not a rebuild: left as it is). A wrap by the
// matrix's name cannot tell the two apart, so the splice declines with the reason and SPIRV-Cross
// re-emits the IR fix, which knows each product.
// RUN: %stereoshift --validate-each %s -o %t.frag 2>&1 | FileCheck %s --check-prefix=NOTE
// RUN: %rmchecks %t.frag | FileCheck %s
// NOTE: note: GLSL re-emitted by SPIRV-Cross instead of spliced into its own text: the text has 2 product(s) `uInvViewProj * ...`, the analysis fixed 1
// CHECK-NOT: stereoshift_unproject_
// CHECK: uInvViewProj[0] * ((eyeSign * separation)
in vec2 vUV;
uniform sampler2D uDepth;
uniform mat4 uInvViewProj;
out vec4 fragColor;

void main()
{
    float depth = texture(uDepth, vUV).r;
    vec4 q = uInvViewProj * vec4(vUV * 2.0 - 1.0, depth * 2.0 - 1.0, 1.0);
    vec4 origin = uInvViewProj * vec4(0.0, 0.0, -1.0, 1.0);
    fragColor = vec4(q.xyz / q.w - origin.xyz / origin.w, 1.0);
}
