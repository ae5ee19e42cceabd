#version 450
// stereoshift-expect: deferred-unproject
// Vulkan SSAO: view-space position from the interpolated far-plane ray times the linear depth
// (depth / far) of the G-buffer, a hemisphere kernel around the normal, each sample projected back
// with the camera projection to compare against the depth buffer.

layout(set = 0, binding = 1) uniform SsaoParams {
    mat4 projection;
    vec4 samples[16];
    vec2 noiseScale;
    float radius;
    float bias;
} ssao;

layout(set = 1, binding = 0) uniform sampler2D gLinearDepth;   // view depth / far
layout(set = 1, binding = 1) uniform sampler2D gNormal;        // view-space normal
layout(set = 1, binding = 2) uniform sampler2D noiseTex;

layout(location = 0) in vec2 inUV;
layout(location = 1) in vec3 inViewRay;
layout(location = 0) out float outOcclusion;

/* ---- stereoshift ---- */ vec3 stereoshift_view_ray_fragPos(vec3 stereoshift_p); /* ---- end stereoshift ---- */ /* ---- stereoshift ---- */ vec4 stereoshift_reproject_ssao_projection(vec4 stereoshift_q); /* ---- end stereoshift ---- */ void main()
{
    vec3 fragPos = stereoshift_view_ray_fragPos(inViewRay * texture(gLinearDepth, inUV).r);
    vec3 normal = normalize(texture(gNormal, inUV).xyz);
    vec3 randomVec = normalize(texture(noiseTex, inUV * ssao.noiseScale).xyz);
    vec3 tangent = normalize(randomVec - normal * dot(randomVec, normal));
    mat3 TBN = mat3(tangent, cross(normal, tangent), normal);

    float occlusion = 0.0;
    for (int i = 0; i < 16; ++i) {
        vec3 samplePos = fragPos + TBN * ssao.samples[i].xyz * ssao.radius;
        vec4 offset = stereoshift_reproject_ssao_projection(ssao.projection * vec4(samplePos, 1.0));
        offset.xy = offset.xy / offset.w * 0.5 + 0.5;
        vec3 sampleRay = inViewRay;
        float sampleDepth = -texture(gLinearDepth, offset.xy).r * -sampleRay.z;
        float rangeCheck = smoothstep(0.0, 1.0, ssao.radius / abs(fragPos.z - sampleDepth));
        occlusion += (sampleDepth >= samplePos.z + ssao.bias ? 1.0 : 0.0) * rangeCheck;
    }
    outOcclusion = 1.0 - occlusion / 16.0;
}
// ---- stereoshift: stereo parameters and per-eye helpers (injected) ----
layout(set = 0, binding = 2, std140) uniform StereoParams
{
    float eyeSign;
    float separation;
    float convergence;
} stereo;
vec4 stereoshift_reproject_ssao_projection(vec4 stereoshift_q)
{
    return stereo.eyeSign != 0.0 ? vec4(stereoshift_q.x + (stereo.eyeSign * stereo.separation) * (stereoshift_q.w - stereo.convergence), stereoshift_q.yzw) : stereoshift_q;
}
vec3 stereoshift_view_ray_fragPos(vec3 stereoshift_p)
{
    if (stereo.eyeSign != 0.0)
        stereoshift_p.x = stereoshift_p.x - ((stereo.eyeSign * stereo.separation) * (abs(stereoshift_p.z) - stereo.convergence)) * (1.0 / ssao.projection[0][0]);
    return stereoshift_p;
}
// ---- end stereoshift ----
