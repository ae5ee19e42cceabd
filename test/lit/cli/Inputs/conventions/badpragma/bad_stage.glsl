#version 450
#pragma shader_stage(vortex)
void main() {}
