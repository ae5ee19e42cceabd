#version 300 es
// stereoshift-expect: shift
// GL ES SDK-style per-vertex lighting vertex shader (`.vsh`).
uniform highp mat4 u_mvpMatrix;
uniform highp mat3 u_normalMatrix;
uniform highp vec3 u_lightDirection;
in highp vec4 a_position;
in highp vec3 a_normal;
in mediump vec2 a_texCoord;
out mediump vec2 v_texCoord;
out lowp float v_diffuse;

void main_stereoshift_mono()
{
    gl_Position = u_mvpMatrix * a_position;
    v_texCoord = a_texCoord;
    v_diffuse = max(dot(normalize(u_normalMatrix * a_normal), u_lightDirection), 0.0);
}
// ---- stereoshift: stereo parameters and clip-space shift (injected) ----
uniform float eyeSign;
uniform float separation;
uniform float convergence;
void main()
{
    main_stereoshift_mono();
    if (eyeSign != 0.0 && abs(gl_Position.w - 1.0) > 9.99999975e-06 && !isinf(gl_Position.w))
    {
        gl_Position.x = gl_Position.x + (eyeSign * separation) * (gl_Position.w - convergence);
    }
}
// ---- end stereoshift ----
