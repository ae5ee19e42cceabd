#version 100
// stereoshift-expect: shift
// GL ES 2.0 SDK style vertex shader: a_/u_/v_ naming, one MVP matrix, texture coordinates passed on.
uniform mat4 u_mvpMatrix;

attribute vec4 a_position;
attribute vec2 a_texCoord;

varying vec2 v_texCoord;

void main_stereoshift_mono()
{
    gl_Position = u_mvpMatrix * a_position;
    v_texCoord = a_texCoord;
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
