#version 450
// stereoshift-expect: fragment
// Vulkan forward PBR fragment shader: GGX specular + Lambert from one directional light (camera position only for shading).

layout(set = 0, binding = 0) uniform CameraUBO {
    mat4 view;
    mat4 proj;
    vec4 cameraPos;
} camera;

layout(set = 1, binding = 0) uniform MaterialUBO {
    vec4 lightDir;      // xyz direction, w intensity
    vec4 lightColor;
    float roughness;
    float metallic;
} material;

layout(set = 1, binding = 1) uniform sampler2D albedoTex;

layout(location = 0) in vec3 inWorldPos;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec2 inUV;

layout(location = 0) out vec4 outColor;

const float PI = 3.14159265;

void main()
{
    vec3 albedo = texture(albedoTex, inUV).rgb;
    vec3 n = normalize(inNormal);
    vec3 v = normalize(camera.cameraPos.xyz - inWorldPos);
    vec3 l = normalize(-material.lightDir.xyz);
    vec3 h = normalize(v + l);

    float a = material.roughness * material.roughness;
    float ndh = max(dot(n, h), 0.0);
    float d = a * a / (PI * pow(ndh * ndh * (a * a - 1.0) + 1.0, 2.0));
    vec3 f0 = mix(vec3(0.04), albedo, material.metallic);
    vec3 f = f0 + (1.0 - f0) * pow(1.0 - max(dot(h, v), 0.0), 5.0);

    float ndl = max(dot(n, l), 0.0);
    vec3 diffuse = (1.0 - material.metallic) * albedo / PI;
    vec3 radiance = material.lightColor.rgb * material.lightDir.w;
    outColor = vec4((diffuse + f * d * 0.25) * radiance * ndl + albedo * 0.03, 1.0);
}
