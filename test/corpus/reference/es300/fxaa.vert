#version 300 es
// stereoshift-expect: 2d
// Anti-aliasing post-process vertex shader: full-screen triangle from gl_VertexID with w = 1.0 and texel offsets.

precision highp float;

uniform highp vec2 uInvResolution;

out highp vec2 vUV;
out highp vec4 vNeighbourUV;   // xy = top-left, zw = bottom-right

void main()
{
    vec2 pos = vec2(gl_VertexID == 1 ? 3.0 : -1.0, gl_VertexID == 2 ? 3.0 : -1.0);
    vUV = pos * 0.5 + 0.5;
    vNeighbourUV = vec4(vUV - 0.5 * uInvResolution, vUV + 0.5 * uInvResolution);
    gl_Position = vec4(pos, 0.0, 1.0);
}
