#version 130
// stereoshift-expect: fragment
// GLSL 1.30 mesh fragment shader: its own `out vec4` colour and the texture() built-in.
in vec3 fragNormal;
in vec2 fragTexcoord;

uniform sampler2D diffuseMap;
uniform vec3 lightDir;

out vec4 outColor;

void main()
{
    float shade = max(dot(normalize(fragNormal), -lightDir), 0.1);
    outColor = vec4(texture(diffuseMap, fragTexcoord).rgb * shade, 1.0);
}
