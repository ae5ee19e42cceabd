#version 300 es
// stereoshift-expect: deferred-unproject
// Deferred lighting fragment shader: world position from sampled depth and the full-screen UV through uInvViewProj.

precision mediump float;

in highp vec2 vUV;

uniform highp sampler2D uDepthTex;
uniform sampler2D uAlbedoRough;
uniform sampler2D uNormalMetal;
uniform highp mat4 uInvViewProj;
uniform highp vec3 uPointLightPos;
uniform vec3 uPointLightColor;
uniform float uPointLightRadius;

out vec4 fragColor;

/* ---- stereoshift ---- */ highp vec4 stereoshift_unproject_uInvViewProj(highp vec4 stereoshift_q); /* ---- end stereoshift ---- */ void main()
{
    highp float depth = texture(uDepthTex, vUV).r;
    highp vec4 q = stereoshift_unproject_uInvViewProj(uInvViewProj * vec4(vUV * 2.0 - 1.0, depth * 2.0 - 1.0, 1.0));
    highp vec3 worldPos = q.xyz / q.w;

    vec4 albedoRough = texture(uAlbedoRough, vUV);
    vec3 n = normalize(texture(uNormalMetal, vUV).xyz * 2.0 - 1.0);

    highp vec3 toLight = uPointLightPos - worldPos;
    float dist = length(toLight);
    float atten = clamp(1.0 - dist / uPointLightRadius, 0.0, 1.0);
    atten *= atten;
    float ndl = max(dot(n, toLight / dist), 0.0);
    fragColor = vec4(albedoRough.rgb * uPointLightColor * ndl * atten, 1.0);
}
// ---- stereoshift: stereo parameters and per-eye helpers (injected) ----
uniform highp float eyeSign;
uniform highp float separation;
uniform highp float convergence;
highp vec4 stereoshift_unproject_uInvViewProj(highp vec4 stereoshift_q)
{
    return eyeSign != 0.0 ? stereoshift_q - uInvViewProj[0] * ((eyeSign * separation) * (1.0 - convergence * stereoshift_q.w)) : stereoshift_q;
}
// ---- end stereoshift ----
