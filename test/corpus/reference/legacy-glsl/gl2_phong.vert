#version 110
// stereoshift-expect: shift
// GL 2.x tutorial per-pixel Phong vertex shader: gl_NormalMatrix, gl_ModelViewMatrix, gl_Vertex and ftransform().
varying vec3 normal;
varying vec3 eyePosition;

void main_stereoshift_mono()
{
    normal = normalize(gl_NormalMatrix * gl_Normal);
    eyePosition = vec3(gl_ModelViewMatrix * gl_Vertex);
    gl_Position = ftransform();
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
