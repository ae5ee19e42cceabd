#version 100
// stereoshift-expect: shift
// GL ES 2.0 SDK style multiple-render-target vertex shader: position, normal and a world-space position varying.
uniform mat4 u_mvpMatrix;
uniform mat4 u_modelMatrix;

attribute vec4 a_position;
attribute vec3 a_normal;

varying vec3 v_normal;
varying vec3 v_worldPos;

void main_stereoshift_mono()
{
    v_normal = mat3(u_modelMatrix) * a_normal;
    v_worldPos = (u_modelMatrix * a_position).xyz;
    gl_Position = u_mvpMatrix * a_position;
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
