#version 300 es
// stereoshift-expect: fragment
// G-buffer geometry-pass fragment shader: writes albedo/roughness and encoded normal/metalness to two targets.

precision mediump float;

in vec3 vNormal;
in vec3 vTangent;
in vec3 vBitangent;
in vec2 vTexCoord;

uniform sampler2D uAlbedoMap;
uniform sampler2D uNormalMap;
uniform sampler2D uRoughMetalMap;

layout(location = 0) out vec4 outAlbedoRough;
layout(location = 1) out vec4 outNormalMetal;

void main()
{
    vec3 tn = texture(uNormalMap, vTexCoord).xyz * 2.0 - 1.0;
    mat3 tbn = mat3(normalize(vTangent), normalize(vBitangent), normalize(vNormal));
    vec3 n = normalize(tbn * tn);
    vec2 roughMetal = texture(uRoughMetalMap, vTexCoord).gb;

    outAlbedoRough = vec4(texture(uAlbedoMap, vTexCoord).rgb, roughMetal.x);
    outNormalMetal = vec4(n * 0.5 + 0.5, roughMetal.y);
}
