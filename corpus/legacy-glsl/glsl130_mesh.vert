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

void main()
{
    fragNormal = mat3(model) * normal;
    fragTexcoord = texcoord;
    gl_Position = projection * view * model * vec4(position, 1.0);
}
