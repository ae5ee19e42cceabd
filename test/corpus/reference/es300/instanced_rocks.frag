#version 300 es
// stereoshift-expect: fragment
// Instanced rock-field fragment shader: tinted albedo with wrap lighting and a detail texture.

precision mediump float;

in vec3 vNormal;
in vec2 vTexCoord;
in vec3 vTint;

uniform sampler2D uAlbedo;
uniform sampler2D uDetail;
uniform vec3 uSunDir;
uniform float uDetailTiling;

out vec4 fragColor;

void main()
{
    vec3 base = texture(uAlbedo, vTexCoord).rgb * vTint;
    base *= texture(uDetail, vTexCoord * uDetailTiling).rgb * 2.0;
    float wrap = clamp((dot(normalize(vNormal), -uSunDir) + 0.3) / 1.3, 0.0, 1.0);
    fragColor = vec4(base * (0.2 + 0.8 * wrap), 1.0);
}
