#version 450
#extension GL_KHR_shader_subgroup_arithmetic : require
layout(set = 0, binding = 0) uniform Camera { mat4 viewProj; } camera;
layout(location = 0) in vec3 inPos;
layout(location = 0) out float averageHeight;
void main()
{
    averageHeight = subgroupAdd(inPos.y) / float(gl_SubgroupSize);
    gl_Position = camera.viewProj * vec4(inPos, 1.0);
}
