#version 140
// stereoshift-expect: shift
// GLSL 1.40 instanced grid vertex shader: a std140 uniform block and gl_InstanceID offsets.
in vec3 position;

layout(std140) uniform Camera {
    mat4 viewProjection;
    vec4 gridSpacing;
};

out float instanceShade;

void main()
{
    float column = float(gl_InstanceID % 16);
    float row = float(gl_InstanceID / 16);
    vec3 offset = vec3(column, 0.0, row) * gridSpacing.xyz;
    instanceShade = float(gl_InstanceID) / 256.0;
    gl_Position = viewProjection * vec4(position + offset, 1.0);
}
