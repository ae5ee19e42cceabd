#version 140
// stereoshift-expect: shift
// GLSL 1.40 instanced grid vertex shader: a std140 uniform block and gl_InstanceID offsets.
in vec3 position;

layout(std140) uniform Camera {
    mat4 viewProjection;
    vec4 gridSpacing;
};

out float instanceShade;

void main_stereoshift_mono()
{
    float column = float(gl_InstanceID % 16);
    float row = float(gl_InstanceID / 16);
    vec3 offset = vec3(column, 0.0, row) * gridSpacing.xyz;
    instanceShade = float(gl_InstanceID) / 256.0;
    gl_Position = viewProjection * vec4(position + offset, 1.0);
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
