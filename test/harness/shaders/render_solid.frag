#version 450
layout(set = 0, binding = 0) uniform Colour { vec4 colour; } u;
layout(location = 0) out vec4 outColour;
void main() { outColour = u.colour; }
