#version 330 core
// stereoshift-expect: shift
// LearnOpenGL-style lighting vertex shader (`x.y.name.vs`, same stem before the stage as its `.fs`).
layout (location = 0) in vec3 aPos;
layout (location = 1) in vec3 aNormal;

out vec3 FragPos;
out vec3 Normal;

uniform mat4 model;
uniform mat4 view;
uniform mat4 projection;

void main_stereoshift_mono()
{
    FragPos = vec3(model * vec4(aPos, 1.0));
    Normal = mat3(transpose(inverse(model))) * aNormal;
    gl_Position = projection * view * vec4(FragPos, 1.0);
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
