#version 450
// stereoshift-expect: fragment
// Relief-mapped decal, fragment stage: linear then binary search along the tangent-space view ray.
layout (set = 2, binding = 0) uniform sampler2D reliefMap;
layout (set = 2, binding = 1) uniform sampler2D albedoMap;
layout (push_constant) uniform Params { float depthScale; } params;

layout (location = 0) in vec2 inTexCoord;
layout (location = 1) in vec3 inTangentEye;
layout (location = 2) in vec3 inTangentPosition;

layout (location = 0) out vec4 outColor;

void main()
{
	vec3 ray = normalize(inTangentPosition - inTangentEye);
	vec2 stepUV = ray.xy * params.depthScale / (-ray.z * 16.0);
	vec2 uv = inTexCoord;
	float depth = 0.0;
	for (int i = 0; i < 16; ++i) {
		if (depth >= 1.0 - texture(reliefMap, uv).r) break;
		uv += stepUV;
		depth += 1.0 / 16.0;
	}
	for (int i = 0; i < 5; ++i) {
		stepUV *= 0.5;
		uv += (depth < 1.0 - texture(reliefMap, uv).r) ? stepUV : -stepUV;
	}
	outColor = texture(albedoMap, uv);
}
