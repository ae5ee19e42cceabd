#version 450
// Emits two points per input point; the geometry stage is the captured one (stride 32).
layout(points) in;
layout(points, max_vertices = 2) out;
in gl_PerVertex { vec4 gl_Position; } gl_in[];

layout(xfb_buffer = 0, xfb_stride = 32) out;
out gl_PerVertex { layout(xfb_buffer = 0, xfb_offset = 0) vec4 gl_Position; float gl_PointSize; };
layout(location = 0, xfb_buffer = 0, xfb_offset = 16) out vec4 gData;

void main() {
  for (int k = 0; k < 2; ++k) {
    gl_Position = gl_in[0].gl_Position + vec4(0.25 * float(k), -0.5 * float(k), 0.0, 0.0);
    gl_PointSize = 1.0;  // points out + shaderTessellationAndGeometryPointSize: must be written
    gData = vec4(float(gl_PrimitiveIDIn), float(k), float(gl_InvocationID), 7.0);
    EmitVertex();
    EndPrimitive();
  }
}
