#version 330
// stereoshift-expect: 2d
// Deferred directional-light pass vertex shader: full-screen triangle from gl_VertexID at w = 1.0.

out vec2 vUV;

const vec2 kCorners[3] = vec2[3](
    vec2(-1.0, -1.0),
    vec2( 3.0, -1.0),
    vec2(-1.0,  3.0)
);

void main()
{
    vec2 ndc = kCorners[gl_VertexID];
    vUV = ndc * 0.5 + 0.5;
    gl_Position = vec4(ndc, 1.0, 1.0);
}
