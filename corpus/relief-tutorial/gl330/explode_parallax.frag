#version 330 core
// stereoshift-expect: fragment
// Exploding parallax-mapped model, fragment stage: the view direction from the geometry stage's varyings offsets the texture coordinates.
out vec4 FragColor;

in GS_OUT {
    vec2 TexCoords;
    vec3 TangentViewPos;
    vec3 TangentFragPos;
} fs_in;

uniform sampler2D diffuseMap;
uniform sampler2D depthMap;
uniform float heightScale;

vec2 ParallaxMapping(vec2 texCoords, vec3 viewDir)
{
    float height = texture(depthMap, texCoords).r;
    return texCoords - viewDir.xy / viewDir.z * (height * heightScale);
}

void main()
{
    vec3 viewDir = normalize(fs_in.TangentViewPos - fs_in.TangentFragPos);
    vec2 texCoords = ParallaxMapping(fs_in.TexCoords, viewDir);
    FragColor = vec4(texture(diffuseMap, texCoords).rgb, 1.0);
}
