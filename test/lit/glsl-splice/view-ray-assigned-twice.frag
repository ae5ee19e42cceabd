#version 330 core
// The changed/unchanged pair of view-ray-and-reprojection.frag: here the local that holds the
// corrected view-ray position is assigned a second time (sky pixels set to zero), so which
// assignment of the text holds the product is not plain from the text: the splice declines with the
// reason and SPIRV-Cross re-emits the IR fix, which knows the product.
// RUN: %stereoshift --validate-each %s -o %t.frag 2>&1 | FileCheck %s --check-prefix=NOTE
// RUN: %rmchecks %t.frag | FileCheck %s
// NOTE: note: GLSL re-emitted by SPIRV-Cross instead of spliced into its own text: the splice cannot write a view ray whose corrected value is not the one value a local of the text is assigned
// CHECK-NOT: stereoshift_view_ray_
// CHECK: ((eyeSign * separation) * ({{.*}} - convergence)) * uInvProjection[0].x
uniform sampler2D uDepth;
uniform mat4 uInvProjection;
in vec2 vUV;
out vec4 fragColor;

void main()
{
    vec4 farCorner = uInvProjection * vec4(vUV * 2.0 - 1.0, 1.0, 1.0);
    vec3 ray = farCorner.xyz / farCorner.w;
    float viewDepth = texture(uDepth, vUV).r;
    vec3 position = ray * (viewDepth / -ray.z);
    if (viewDepth <= 0.0)
        position = vec3(0.0);
    fragColor = vec4(fract(position), 1.0);
}
