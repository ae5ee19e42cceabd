#version 450
// Feeds the geometry / tessellation capture tests: no capture here, and no gl_PointSize (only the
// last pre-rasterization stage must write it for points; the gl_PerVertex blocks of consecutive
// stages must match for the validation layer).
layout(location = 0) in vec4 inPos;
out gl_PerVertex { vec4 gl_Position; };
void main() { gl_Position = inPos; }
