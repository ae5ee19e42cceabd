#version 450
#pragma shader_stage(vertex)
layout(location = 0) in vec3 inPos;
layout(set = 0, binding = 0) uniform Camera { mat4 viewProj; } camera;
layout(location = 0) out vec3 outDir;
void main()
{
    outDir = inPos;
    gl_Position = camera.viewProj * vec4(inPos, 1.0);
}
