#version 330
// stereoshift-expect: fragment
// Skinned character fragment shader: half-Lambert diffuse with linear distance fog.

in vec3 vNormal;
in vec2 vTexCoord;
in float vViewDepth;

uniform sampler2D uDiffuseMap;
uniform vec3 uLightDir;
uniform vec3 uFogColor;
uniform vec2 uFogRange;

out vec4 fragColor;

void main()
{
    vec3 n = normalize(vNormal);
    float halfLambert = dot(n, normalize(-uLightDir)) * 0.5 + 0.5;
    vec4 base = texture(uDiffuseMap, vTexCoord);
    vec3 lit = base.rgb * halfLambert * halfLambert;

    float fog = clamp((vViewDepth - uFogRange.x) / (uFogRange.y - uFogRange.x), 0.0, 1.0);
    fragColor = vec4(mix(lit, uFogColor, fog), base.a);
}
