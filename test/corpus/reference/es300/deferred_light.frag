#version 300 es
precision mediump float;
precision highp int;

uniform highp sampler2D uDepthTex;
uniform highp mat4 uInvViewProj;
uniform mediump sampler2D uAlbedoRough;
uniform mediump sampler2D uNormalMetal;
uniform highp vec3 uPointLightPos;
uniform float uPointLightRadius;
uniform vec3 uPointLightColor;
uniform highp float eyeSign;
uniform highp float separation;
uniform highp float convergence;

in highp vec2 vUV;
out vec4 fragColor;

void main()
{
    highp float depth = texture(uDepthTex, vUV).x;
    highp vec4 _41 = uInvViewProj * vec4((vUV * 2.0) - vec2(1.0), (depth * 2.0) - 1.0, 1.0);
    highp vec4 _126 = _41 - (uInvViewProj[0] * ((eyeSign * separation) * (1.0 - (convergence * _41.w))));
    bvec4 _128 = bvec4(eyeSign != 0.0);
    highp vec4 q = vec4(_128.x ? _126.x : _41.x, _128.y ? _126.y : _41.y, _128.z ? _126.z : _41.z, _128.w ? _126.w : _41.w);
    highp vec3 worldPos = q.xyz / vec3(q.w);
    vec4 albedoRough = texture(uAlbedoRough, vUV);
    vec3 n = normalize((texture(uNormalMetal, vUV).xyz * 2.0) - vec3(1.0));
    highp vec3 toLight = uPointLightPos - worldPos;
    float dist = length(toLight);
    float atten = clamp(1.0 - (dist / uPointLightRadius), 0.0, 1.0);
    atten *= atten;
    float ndl = max(dot(n, toLight / vec3(dist)), 0.0);
    fragColor = vec4(((albedoRough.xyz * uPointLightColor) * ndl) * atten, 1.0);
}

