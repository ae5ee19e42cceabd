#version 460
// A bindless-style Vulkan vertex shader: vertex pulling and the camera through buffer device
// addresses held in the push constants (GL_EXT_buffer_reference), as GPU-driven renderers write it.
#extension GL_EXT_buffer_reference : require
#extension GL_EXT_scalar_block_layout : require

layout(buffer_reference, scalar) readonly buffer VertexBuffer { vec3 positions[]; };
layout(buffer_reference, std430) readonly buffer CameraBuffer { mat4 view; mat4 proj; };

layout(push_constant) uniform DrawConstants {
    VertexBuffer vertices;
    CameraBuffer camera;
    mat4 model;
} draw;

layout(location = 0) out vec3 vWorld;

void main()
{
    vec4 world = draw.model * vec4(draw.vertices.positions[gl_VertexIndex], 1.0);
    vWorld = world.xyz;
    gl_Position = draw.camera.proj * (draw.camera.view * world);
}
