#version 330
// stereoshift-expect: shift
// Shadow-map depth pass vertex shader using a light-space MVP (a mono pass: the draw, not the shader, decides).

layout(location = 0) in vec3 aPosition;
in vec2 aTexCoord;

uniform mat4 uLightMVP;
uniform float uDepthBias;

out vec2 vTexCoord;

void main_stereoshift_mono()
{
    vTexCoord = aTexCoord;
    vec4 clip = uLightMVP * vec4(aPosition, 1.0);
    // Constant slope-free bias pushed into clip space.
    clip.z += uDepthBias * clip.w;
    gl_Position = clip;
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
