#version 450

layout(set = 0, binding = 1, std140) uniform SsaoParams
{
    mat4 projection;
    vec4 samples[16];
    vec2 noiseScale;
    float radius;
    float bias;
} ssao;

layout(set = 0, binding = 2, std140) uniform StereoParams
{
    float eyeSign;
    float separation;
    float convergence;
} stereo;

layout(set = 1, binding = 0) uniform sampler2D gLinearDepth;
layout(set = 1, binding = 1) uniform sampler2D gNormal;
layout(set = 1, binding = 2) uniform sampler2D noiseTex;

layout(location = 1) in vec3 inViewRay;
layout(location = 0) in vec2 inUV;
layout(location = 0) out float outOcclusion;

void main()
{
    vec3 _27 = inViewRay * texture(gLinearDepth, inUV).x;
    float _201 = _27.z;
    vec3 _211 = _27;
    _211.x = _27.x - (((stereo.eyeSign * stereo.separation) * (((_201 < 0.0) ? (-_201) : _201) - stereo.convergence)) * (1.0 / ssao.projection[0].x));
    vec3 fragPos = mix(_27, _211, bvec3(stereo.eyeSign != 0.0));
    vec3 normal = normalize(texture(gNormal, inUV).xyz);
    vec3 randomVec = normalize(texture(noiseTex, inUV * ssao.noiseScale).xyz);
    vec3 tangent = normalize(randomVec - (normal * dot(randomVec, normal)));
    mat3 TBN = mat3(vec3(tangent), vec3(cross(normal, tangent)), vec3(normal));
    float occlusion = 0.0;
    for (int i = 0; i < 16; i++)
    {
        vec3 samplePos = fragPos + ((TBN * ssao.samples[i].xyz) * ssao.radius);
        vec4 _126 = ssao.projection * vec4(samplePos, 1.0);
        precise float _224 = _126.w - stereo.convergence;
        precise float _225 = stereo.eyeSign * stereo.separation;
        precise float _226 = _225 * _224;
        precise float _227 = _126.x + _226;
        vec4 _228 = _126;
        _228.x = _227;
        vec4 offset = mix(_126, _228, bvec4(stereo.eyeSign != 0.0));
        vec4 _127 = offset;
        float _131 = offset.w;
        vec2 _137 = ((_127.xy / vec2(_131)) * 0.5) + vec2(0.5);
        offset.x = _137.x;
        offset.y = _137.y;
        vec3 sampleRay = inViewRay;
        float sampleDepth = (-texture(gLinearDepth, offset.xy).x) * (-sampleRay.z);
        float rangeCheck = smoothstep(0.0, 1.0, ssao.radius / abs(fragPos.z - sampleDepth));
        occlusion += (float(sampleDepth >= (samplePos.z + ssao.bias)) * rangeCheck);
    }
    outOcclusion = 1.0 - (occlusion / 16.0);
}

