#version 330
// stereoshift-expect: fragment
// Forward Blinn-Phong fragment shader; the camera position feeds only the specular term (mono eye is fine).

in vec3 vWorldPos;
in vec3 vNormal;
in vec2 vTexCoord;

uniform sampler2D uAlbedo;
uniform vec3 uCameraPos;
uniform vec3 uLightDir;
uniform vec3 uLightColor;
uniform vec3 uAmbient;
uniform float uShininess;

layout(location = 0) out vec4 fragColor;

void main()
{
    vec4 albedo = texture(uAlbedo, vTexCoord);
    vec3 n = normalize(vNormal);
    vec3 l = normalize(-uLightDir);
    vec3 v = normalize(uCameraPos - vWorldPos);
    vec3 h = normalize(l + v);

    float diffuse = max(dot(n, l), 0.0);
    float specular = diffuse > 0.0 ? pow(max(dot(n, h), 0.0), uShininess) : 0.0;

    vec3 color = albedo.rgb * (uAmbient + uLightColor * diffuse) + uLightColor * specular * 0.25;
    fragColor = vec4(color, albedo.a);
}
