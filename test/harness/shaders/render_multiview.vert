#version 450
#extension GL_EXT_multiview : require
// View 0 (left eye) moves by -shift in NDC x, view 1 (right eye) by +shift.
layout(location = 0) in vec3 inPos;
layout(push_constant) uniform Push { float shift; } pc;
void main() {
  float e = gl_ViewIndex == 0 ? -1.0 : 1.0;
  gl_Position = vec4(inPos.x + e * pc.shift, inPos.y, inPos.z, 1.0);
}
