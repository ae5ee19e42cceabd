#version 450
// Push constants and specialization constants, observed through the captured outputs.
layout(location = 0) in vec4 inPos;
layout(push_constant) uniform Push { vec4 offset; uint tag; } pc;
layout(constant_id = 7) const float SCALE = 1.0;
layout(constant_id = 8) const int COUNT = 3;
layout(constant_id = 9) const bool FLAG = false;

out gl_PerVertex { layout(xfb_buffer = 0, xfb_offset = 0, xfb_stride = 32) vec4 gl_Position; float gl_PointSize; };
layout(location = 0, xfb_buffer = 0, xfb_offset = 16) flat out uvec4 vInfo;

void main() {
  gl_Position = inPos * SCALE + pc.offset;
  gl_PointSize = 1.0;  // point list: Vulkan requires PointSize to be written
  vInfo = uvec4(pc.tag, uint(COUNT), FLAG ? 1u : 0u, uint(gl_VertexIndex));
}
