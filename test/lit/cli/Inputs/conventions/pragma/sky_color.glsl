#version 450
#pragma shader_stage(fragment)
#include "noise.glsl"
layout(location = 0) in vec3 inDir;
layout(location = 0) out vec4 outColor;
void main()
{
    outColor = vec4(vec3(hash(inDir.y)), 1.0);
}
