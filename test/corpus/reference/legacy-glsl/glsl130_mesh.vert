#version 130
// stereoshift-expect: shift
// GLSL 1.30 mesh vertex shader: in/out storage, separate model, view and projection matrices.
in vec3 position;
in vec3 normal;
in vec2 texcoord;

uniform mat4 model;
uniform mat4 view;
uniform mat4 projection;

out vec3 fragNormal;
out vec2 fragTexcoord;

void main_stereoshift_mono()
{
    fragNormal = mat3(model) * normal;
    fragTexcoord = texcoord;
    gl_Position = projection * view * model * vec4(position, 1.0);
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
