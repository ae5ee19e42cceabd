#version 450
// Captured stage: barycentric position, tessellation coordinate and patch id (stride 32).
layout(triangles, equal_spacing, ccw) in;
in gl_PerVertex { vec4 gl_Position; } gl_in[gl_MaxPatchVertices];

layout(xfb_buffer = 0, xfb_stride = 32) out;
out gl_PerVertex { layout(xfb_buffer = 0, xfb_offset = 0) vec4 gl_Position; };
layout(location = 0, xfb_buffer = 0, xfb_offset = 16) out vec3 tCoord;
layout(location = 1, xfb_buffer = 0, xfb_offset = 28) out float tPatch;

void main() {
  vec3 c = gl_TessCoord;
  gl_Position = c.x * gl_in[0].gl_Position + c.y * gl_in[1].gl_Position + c.z * gl_in[2].gl_Position;
  tCoord = c;
  tPatch = float(gl_PrimitiveID);
}
