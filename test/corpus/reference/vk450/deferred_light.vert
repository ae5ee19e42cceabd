#version 450
// stereoshift-expect: 2d
// Vulkan deferred lighting vertex shader: full-screen triangle from gl_VertexIndex with a constant w of 1.0.

layout(location = 0) out vec2 outUV;

out gl_PerVertex {
    vec4 gl_Position;
};

void main()
{
    const vec2 positions[3] = vec2[](vec2(-1.0, -1.0), vec2(3.0, -1.0), vec2(-1.0, 3.0));
    vec2 p = positions[gl_VertexIndex];
    // Vulkan NDC has +y pointing down, which matches the G-buffer's top-left UV origin.
    outUV = p * 0.5 + 0.5;
    gl_Position = vec4(p, 0.0, 1.0);
}
