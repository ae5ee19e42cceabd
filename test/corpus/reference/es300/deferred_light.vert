#version 300 es
// stereoshift-expect: 2d
// Deferred lighting pass vertex shader: full-screen triangle from gl_VertexID, constant w = 1.0.

precision highp float;

out highp vec2 vUV;

void main()
{
    float x = float((gl_VertexID & 1) << 2);
    float y = float((gl_VertexID & 2) << 1);
    vUV = vec2(x, y) * 0.5;
    gl_Position = vec4(x - 1.0, y - 1.0, 0.0, 1.0);
}
