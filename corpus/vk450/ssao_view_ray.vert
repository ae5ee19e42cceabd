#version 450
// stereoshift-expect: 2d
// Vulkan SSAO full-screen pass, vertex stage: one triangle over the screen, and the view-space ray
// through each corner taken from the four far-plane frustum corners the application uploads.

layout(set = 0, binding = 0) uniform SsaoCamera {
    vec4 frustumCorners[4];   // view space, far plane: bottom-left, bottom-right, top-left, top-right
} cameraData;

layout(location = 0) out vec2 outUV;
layout(location = 1) out vec3 outViewRay;

void main()
{
    outUV = vec2((gl_VertexIndex << 1) & 2, gl_VertexIndex & 2);
    // Corner index from the UV quadrant: 0 bottom-left, 1 bottom-right, 2 top-left.
    int corner = int(outUV.x > 0.5) + 2 * int(outUV.y > 0.5);
    outViewRay = cameraData.frustumCorners[min(corner, 3)].xyz;
    gl_Position = vec4(outUV * 2.0 - 1.0, 0.0, 1.0);
}
