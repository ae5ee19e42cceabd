#version 450
// stereoshift-expect: shift
// Vulkan skybox vertex shader: cube vertices at infinity, gl_Position = pos.xyww so depth lands on the far plane.

layout(set = 0, binding = 0) uniform SkyUBO {
    mat4 viewRotation;   // view matrix with the translation removed
    mat4 proj;
    float rotationY;
} sky;

layout(location = 0) in vec3 inPosition;

layout(location = 0) out vec3 outDirection;

void main()
{
    float c = cos(sky.rotationY);
    float s = sin(sky.rotationY);
    vec3 dir = vec3(c * inPosition.x + s * inPosition.z, inPosition.y, -s * inPosition.x + c * inPosition.z);
    outDirection = dir;

    vec4 pos = sky.proj * sky.viewRotation * vec4(inPosition, 1.0);
    gl_Position = pos.xyww;
}
