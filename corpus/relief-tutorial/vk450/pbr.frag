#version 450
// stereoshift-expect: fragment
// Image-based-lighting PBR, fragment stage: the view vector only shades (BRDF table at dot(N, V), prefiltered reflection, specular lobe).
layout (location = 0) in vec3 inWorldPos;
layout (location = 1) in vec3 inNormal;
layout (location = 2) in vec2 inUV;

layout (binding = 0) uniform UBO
{
	mat4 projection;
	mat4 model;
	mat4 view;
	vec3 camPos;
} ubo;

layout (binding = 1) uniform UBOParams
{
	vec4 lightDir;
	float exposure;
	float roughness;
	float metallic;
} uboParams;

layout (binding = 2) uniform samplerCube samplerIrradiance;
layout (binding = 3) uniform sampler2D samplerBRDFLUT;
layout (binding = 4) uniform samplerCube prefilteredMap;
layout (binding = 5) uniform sampler2D albedoMap;

layout (location = 0) out vec4 outColor;

const float PI = 3.14159265359;

float D_GGX(float dotNH, float roughness)
{
	float alpha = roughness * roughness;
	float alpha2 = alpha * alpha;
	float denom = dotNH * dotNH * (alpha2 - 1.0) + 1.0;
	return alpha2 / (PI * denom * denom);
}

vec3 F_SchlickR(float cosTheta, vec3 F0, float roughness)
{
	return F0 + (max(vec3(1.0 - roughness), F0) - F0) * pow(1.0 - cosTheta, 5.0);
}

void main()
{
	vec3 N = normalize(inNormal);
	vec3 V = normalize(ubo.camPos - inWorldPos);
	vec3 R = reflect(-V, N);
	vec3 albedo = texture(albedoMap, inUV).rgb;
	vec3 F0 = mix(vec3(0.04), albedo, uboParams.metallic);

	vec3 L = normalize(uboParams.lightDir.xyz);
	vec3 H = normalize(V + L);
	float dotNH = clamp(dot(N, H), 0.0, 1.0);
	float dotNV = clamp(dot(N, V), 0.0, 1.0);
	vec3 direct = vec3(D_GGX(dotNH, uboParams.roughness)) * clamp(dot(N, L), 0.0, 1.0);

	vec2 brdf = texture(samplerBRDFLUT, vec2(dotNV, uboParams.roughness)).rg;
	vec3 reflection = textureLod(prefilteredMap, R, uboParams.roughness * 9.0).rgb;
	vec3 irradiance = texture(samplerIrradiance, N).rgb;
	vec3 F = F_SchlickR(dotNV, F0, uboParams.roughness);
	vec3 specular = reflection * (F * brdf.x + brdf.y);
	vec3 kD = (1.0 - F) * (1.0 - uboParams.metallic);
	vec3 color = kD * irradiance * albedo + specular + direct;
	color = vec3(1.0) - exp(-color * uboParams.exposure);
	outColor = vec4(color, 1.0);
}
