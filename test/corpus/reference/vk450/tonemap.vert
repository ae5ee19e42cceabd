#version 450
// stereoshift-expect: 2d
// Vulkan post-process vertex shader: full-screen triangle from gl_VertexIndex, clip w = 1.0.

layout(location = 0) out vec2 outUV;

out gl_PerVertex {
    vec4 gl_Position;
};

void main()
{
    // Vertex 0 -> (0,0), 1 -> (2,0), 2 -> (0,2): one triangle covers the viewport.
    vec2 uv = vec2((gl_VertexIndex << 1) & 2, gl_VertexIndex & 2);
    outUV = uv;
    gl_Position = vec4(uv * 2.0 - 1.0, 0.0, 1.0);
}
