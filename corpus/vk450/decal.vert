#version 450
// stereoshift-expect: shift
// Deferred decal box vertex shader: projects the decal volume and also copies the clip position to a varying (halo case).

layout(set = 0, binding = 0) uniform CameraUBO {
    mat4 viewProj;
    mat4 invViewProj;
} camera;

// 80 bytes: within the 128 bytes of push constants every Vulkan device guarantees.
layout(push_constant) uniform DecalPush {
    mat4 decalToWorld;
    vec4 color;
} decal;

layout(location = 0) in vec3 inPosition;   // unit cube in [-0.5, 0.5]

layout(location = 0) out vec4 outClipPos;

void main()
{
    vec4 world = decal.decalToWorld * vec4(inPosition, 1.0);
    gl_Position = camera.viewProj * world;
    outClipPos = gl_Position;
}
