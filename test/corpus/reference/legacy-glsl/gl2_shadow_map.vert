#version 120
// stereoshift-expect: shift
// GL 2.1 tutorial shadow-mapping vertex shader: the light's texture matrix on gl_TextureMatrix[7], ftransform().
varying vec4 shadowCoord;
varying vec3 normal;

void main_stereoshift_mono()
{
    shadowCoord = gl_TextureMatrix[7] * gl_Vertex;
    normal = gl_NormalMatrix * gl_Normal;
    gl_FrontColor = gl_Color;
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
