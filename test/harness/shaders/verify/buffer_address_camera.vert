#version 460
// The camera reached through a 64-bit address stored in a uniform block and cast to a pointer in
// the code (GL_EXT_buffer_reference2 with int64 arithmetic), as scene-graph renderers pass it.
#extension GL_EXT_buffer_reference2 : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require

layout(buffer_reference, std430, buffer_reference_align = 16) readonly buffer Camera { mat4 viewProj; };

layout(set = 0, binding = 0) uniform Frame {
    uint64_t cameraAddress;
    mat4 model;
} frame;

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec2 inUv;
layout(location = 0) out vec2 vUv;

void main()
{
    Camera camera = Camera(frame.cameraAddress);
    vUv = inUv;
    gl_Position = camera.viewProj * frame.model * vec4(inPosition, 1.0);
}
