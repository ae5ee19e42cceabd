#version 450
// Capture test: clip position from a uniform matrix plus a varying, both captured (stride 32).
layout(location = 0) in vec3 inPos;
layout(location = 1) in vec4 inColor;
layout(set = 0, binding = 0) uniform Transform { mat4 mvp; } ubo;

out gl_PerVertex { layout(xfb_buffer = 0, xfb_offset = 0, xfb_stride = 32) vec4 gl_Position; };
layout(location = 0, xfb_buffer = 0, xfb_offset = 16) out vec4 vColor;

void main() {
  gl_Position = ubo.mvp * vec4(inPos, 1.0);
  vColor = inColor * 2.0 + vec4(float(gl_VertexIndex));
}
