#version 300 es
// stereoshift-expect: fragment
// Mobile forward-lit fragment shader: one directional light, Lambert diffuse, texture with alpha test.

precision mediump float;

in vec3 vNormal;
in vec3 vAmbient;
in vec2 vTexCoord;

uniform sampler2D uAlbedo;
uniform vec3 uLightDir;
uniform vec3 uLightColor;
uniform float uAlphaCutoff;

out vec4 fragColor;

void main()
{
    vec4 albedo = texture(uAlbedo, vTexCoord);
    if (albedo.a < uAlphaCutoff)
        discard;
    float ndl = max(dot(normalize(vNormal), -uLightDir), 0.0);
    vec3 color = albedo.rgb * (vAmbient + uLightColor * ndl);
    fragColor = vec4(color, 1.0);
}
