#version 450
#extension GL_EXT_multiview : require
layout(location = 0) out vec4 outColour;
void main() { outColour = gl_ViewIndex == 0 ? vec4(1.0, 0.0, 0.0, 1.0) : vec4(0.0, 1.0, 0.0, 1.0); }
