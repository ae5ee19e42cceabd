#version 330
// stereoshift-expect: deferred-unproject
// Deferred directional-light fragment shader: rebuilds world position from the depth buffer with uInvViewProj.

in vec2 vUV;

uniform sampler2D uGDepth;
uniform sampler2D uGNormal;
uniform sampler2D uGAlbedo;
uniform mat4 uInvViewProj;
uniform vec2 uViewportSize;
uniform vec3 uLightDir;
uniform vec3 uLightColor;
uniform vec3 uCameraPos;

out vec4 fragColor;

/* ---- stereoshift ---- */ vec4 stereoshift_unproject_uInvViewProj(vec4 stereoshift_q); /* ---- end stereoshift ---- */ void main()
{
    float depth = texture(uGDepth, vUV).r;
    if (depth >= 1.0)
        discard;

    vec2 ndc = gl_FragCoord.xy / uViewportSize * 2.0 - 1.0;
    vec4 q = stereoshift_unproject_uInvViewProj(uInvViewProj * vec4(ndc, depth * 2.0 - 1.0, 1.0));
    vec3 worldPos = q.xyz / q.w;

    vec3 n = normalize(texture(uGNormal, vUV).xyz * 2.0 - 1.0);
    vec3 albedo = texture(uGAlbedo, vUV).rgb;
    vec3 l = normalize(-uLightDir);
    vec3 h = normalize(l + normalize(uCameraPos - worldPos));

    float diffuse = max(dot(n, l), 0.0);
    float specular = pow(max(dot(n, h), 0.0), 32.0) * diffuse;
    fragColor = vec4(uLightColor * (albedo * diffuse + specular), 1.0);
}
// ---- stereoshift: stereo parameters and per-eye helpers (injected) ----
uniform float eyeSign;
uniform float separation;
uniform float convergence;
vec4 stereoshift_unproject_uInvViewProj(vec4 stereoshift_q)
{
    return eyeSign != 0.0 ? stereoshift_q - uInvViewProj[0] * ((eyeSign * separation) * (1.0 - convergence * stereoshift_q.w)) : stereoshift_q;
}
// ---- end stereoshift ----
