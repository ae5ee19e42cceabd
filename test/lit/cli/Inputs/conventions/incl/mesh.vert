#version 330 core
#extension GL_GOOGLE_include_directive : require
#include "transform.glsl"
layout(location = 0) in vec3 aPos;
uniform mat4 mvp;
void main()
{
    gl_Position = toClip(mvp, aPos);
}
