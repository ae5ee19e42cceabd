#version 450
// Per-vertex + per-instance attributes, a combined image sampler read in the vertex stage,
// and a uniform buffer in set 2 (set 1 left empty on purpose). Stride 48.
layout(location = 0) in vec2 inPos;     // binding 0, per vertex
layout(location = 3) in vec4 inOffset;  // binding 1, per instance
layout(set = 0, binding = 1) uniform sampler2D tex;
layout(set = 2, binding = 0) uniform Params { vec4 bias; } params;

out gl_PerVertex { layout(xfb_buffer = 0, xfb_offset = 0, xfb_stride = 48) vec4 gl_Position; float gl_PointSize; };
layout(location = 0, xfb_buffer = 0, xfb_offset = 16) out vec4 vTexel;
layout(location = 1, xfb_buffer = 0, xfb_offset = 32) flat out ivec4 vIds;

void main() {
  ivec2 size = textureSize(tex, 0);
  int t = gl_VertexIndex + 3 * gl_InstanceIndex;
  ivec2 ij = ivec2(t % size.x, t / size.x);
  vec2 uv = (vec2(ij) + 0.5) / vec2(size);
  vTexel = textureLod(tex, uv, 0.0);
  gl_Position = vec4(inPos, 0.0, 1.0) + inOffset + params.bias;
  gl_PointSize = 1.0;  // point list: Vulkan requires PointSize to be written
  vIds = ivec4(gl_VertexIndex, gl_InstanceIndex, size);
}
