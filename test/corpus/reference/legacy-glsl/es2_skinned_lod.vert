#version 100
// stereoshift-expect: shift
// GL ES 2.0 style two-bone skinning vertex shader with a height map fetched by texture2DLod (vertex stage).
precision highp float;

uniform mat4 u_viewProjection;
uniform mat4 u_bones[2];
uniform sampler2D u_heightMap;
uniform float u_heightScale;

attribute vec3 a_position;
attribute vec2 a_weights;
attribute vec2 a_uv;

varying vec2 v_uv;

void main_stereoshift_mono()
{
    mat4 skin = u_bones[0] * a_weights.x + u_bones[1] * a_weights.y;
    float height = texture2DLod(u_heightMap, a_uv, 0.0).r * u_heightScale;
    vec4 world = skin * vec4(a_position + vec3(0.0, height, 0.0), 1.0);
    v_uv = a_uv;
    gl_Position = u_viewProjection * world;
}
// ---- stereoshift: stereo parameters and clip-space shift (injected) ----
uniform float eyeSign;
uniform float separation;
uniform float convergence;
void main()
{
    main_stereoshift_mono();
    if (eyeSign != 0.0 && abs(gl_Position.w - 1.0) > 9.99999975e-06 && abs(gl_Position.w) <= 3.40282347e+38)
    {
        gl_Position.x = gl_Position.x + (eyeSign * separation) * (gl_Position.w - convergence);
    }
}
// ---- end stereoshift ----
