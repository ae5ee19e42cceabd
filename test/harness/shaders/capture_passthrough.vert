#version 450
// Feeds the geometry / tessellation capture tests: no capture here.
layout(location = 0) in vec4 inPos;
out gl_PerVertex { vec4 gl_Position; };
void main() { gl_Position = inPos; }
